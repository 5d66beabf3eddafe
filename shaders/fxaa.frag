// SPDX-License-Identifier: MIT
// FXAA (after Timothy Lottes' FXAA, the compact "console" form): find the local edge direction
// from the luma of the four diagonal neighbours and blur along it, two or four taps, keeping the
// two-tap result when the four-tap one leaves the local luma range. Pixels without local
// contrast are kept as they are. Cheaper than multisampling
// on a software renderer; edges come out a little softer.
#version 330 core

in vec2 v_uv;

uniform sampler2D u_color;
uniform vec2 u_texel;  // 1 / image size

out vec4 frag_color;

const float kReduceMin = 1.0 / 128.0;
const float kReduceMul = 1.0 / 8.0;
const float kSpanMax = 8.0;
const float kEdgeThreshold = 1.0 / 8.0;      // local contrast (of the brightest luma) for an edge
const float kEdgeThresholdMin = 1.0 / 24.0;  // and at least this much in dark regions

float Luma(vec3 color) {
  return dot(color, vec3(0.299, 0.587, 0.114));
}

// filtered, `offset` in texture coordinates
vec3 Fetch(vec2 offset) {
  return texture(u_color, v_uv + offset).rgb;
}

// unfiltered neighbour (cheaper on a software renderer), `offset` in pixels
vec3 Neighbour(ivec2 pixel, ivec2 offset) {
  return texelFetch(u_color, pixel + offset, 0).rgb;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  ivec2 last = textureSize(u_color, 0) - 1;
  vec3 middle = Neighbour(pixel, ivec2(0, 0));
  pixel = clamp(pixel, ivec2(1), max(last - 1, ivec2(1)));  // neighbours stay in the image
  float luma_nw = Luma(Neighbour(pixel, ivec2(-1, -1)));
  float luma_ne = Luma(Neighbour(pixel, ivec2(1, -1)));
  float luma_sw = Luma(Neighbour(pixel, ivec2(-1, 1)));
  float luma_se = Luma(Neighbour(pixel, ivec2(1, 1)));
  float luma_m = Luma(middle);
  float luma_min = min(luma_m, min(min(luma_nw, luma_ne), min(luma_sw, luma_se)));
  float luma_max = max(luma_m, max(max(luma_nw, luma_ne), max(luma_sw, luma_se)));
  // no edge here: keep the pixel (most of the image; saves the four blur taps)
  if (luma_max - luma_min < max(kEdgeThresholdMin, luma_max * kEdgeThreshold)) {
    frag_color = vec4(middle, 1.0);
    return;
  }

  vec2 direction = vec2(-((luma_nw + luma_ne) - (luma_sw + luma_se)),
                        (luma_nw + luma_sw) - (luma_ne + luma_se));
  float reduce = max((luma_nw + luma_ne + luma_sw + luma_se) * 0.25 * kReduceMul, kReduceMin);
  float scale = 1.0 / (min(abs(direction.x), abs(direction.y)) + reduce);
  direction = clamp(direction * scale, vec2(-kSpanMax), vec2(kSpanMax)) * u_texel;

  vec3 two_taps =
      0.5 * (Fetch(direction * (1.0 / 3.0 - 0.5)) + Fetch(direction * (2.0 / 3.0 - 0.5)));
  vec3 four_taps = 0.5 * two_taps + 0.25 * (Fetch(direction * -0.5) + Fetch(direction * 0.5));
  float luma_four = Luma(four_taps);
  frag_color = vec4((luma_four < luma_min || luma_four > luma_max) ? two_taps : four_taps, 1.0);
}
