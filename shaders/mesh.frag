// SPDX-License-Identifier: MIT
// Lit meshes: hemispheric ambient + one directional sun with a PCF shadow map, Blinn-Phong
// highlights, a world-space checker on terrains, distance haze, selection tint. Lighting is done
// in linear colour and written as sRGB.
#version 330 core

in vec3 v_world_position;
in vec3 v_world_normal;

uniform vec4 u_color;  // linear colour (the file's sRGB colour squared by the renderer) and alpha
uniform int u_flags;   // 1 terrain, 2 selected, 8 unlit
uniform vec3 u_eye;
uniform vec3 u_light_direction;  // unit, towards the sun
uniform mat4 u_light_view_projection;
uniform sampler2DShadow u_shadow_map;
uniform int u_shadows;
uniform float u_shadow_texel;         // one shadow-map texel, in shadow uv units
uniform float u_shadow_normal_offset;  // world metres along the normal before the lookup
uniform float u_checker_size;          // terrain checker square, m
uniform vec3 u_haze_color;
uniform vec2 u_haze_range;  // haze starts, is complete (m from the eye)

out vec4 frag_color;

const vec3 kSkyAmbient = vec3(0.30, 0.35, 0.44);
const vec3 kGroundAmbient = vec3(0.14, 0.12, 0.10);
const vec3 kSunColor = vec3(1.05, 1.0, 0.92);
const vec3 kSelectedTint = vec3(1.0, 0.62, 0.12);

// gamma 2 approximates sRGB closely enough and costs a square root
vec3 ToLinear(vec3 c) { return c * c; }
vec3 ToSrgb(vec3 c) { return sqrt(clamp(c, 0.0, 1.0)); }

// box-filtered checker in [0, 1] (no aliasing at a distance); w = fwidth(uv)
float Checker(vec2 uv, vec2 w) {
  w += 1e-4;
  vec2 i = 2.0 * (abs(fract((uv - 0.5 * w) * 0.5) - 0.5) - abs(fract((uv + 0.5 * w) * 0.5) - 0.5)) / w;
  return 0.5 - 0.5 * i.x * i.y;
}

// coverage in [0, 1] of one-pixel lines every `period` squares; w = fwidth(uv)
float GridLines(vec2 uv, vec2 w, float period) {
  vec2 d = abs(fract(uv / period - 0.5) - 0.5) * period / max(w, 1e-4);
  return 1.0 - min(min(d.x, d.y), 1.0);
}

vec2 TerrainUv(vec3 p, vec3 n) {
  vec3 a = abs(n);
  if (a.z >= a.x && a.z >= a.y) return p.xy;
  return a.x >= a.y ? p.yz : p.xz;
}

float Shadow(vec3 p, vec3 n) {
  if (u_shadows == 0) return 1.0;
  vec4 lp = u_light_view_projection * vec4(p + n * u_shadow_normal_offset, 1.0);
  vec3 uvz = lp.xyz / lp.w * 0.5 + 0.5;
  if (uvz.z >= 1.0 || any(lessThan(uvz.xy, vec2(0.0))) || any(greaterThan(uvz.xy, vec2(1.0)))) {
    return 1.0;
  }
  // two bilinear (2x2 PCF) lookups half a texel apart: a soft edge for 8 depth fetches
  vec2 offset = vec2(0.5 * u_shadow_texel);
  return 0.5 * (texture(u_shadow_map, vec3(uvz.xy - offset, uvz.z)) +
                texture(u_shadow_map, vec3(uvz.xy + offset, uvz.z)));
}

void main() {
  if ((u_flags & 8) != 0) {
    frag_color = vec4(ToSrgb(u_color.rgb), u_color.a);
    return;
  }
  vec3 n = normalize(v_world_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 p = v_world_position;
  vec3 base = u_color.rgb;
  if ((u_flags & 1) != 0) {
    vec2 uv = TerrainUv(p, n) / u_checker_size;
    vec2 w = fwidth(uv);
    base *= mix(0.72, 1.0, Checker(uv, w)) * (1.0 - 0.3 * GridLines(uv, w, 5.0));
  }
  vec3 view = normalize(u_eye - p);
  float n_dot_l = max(dot(n, u_light_direction), 0.0);
  float shadow = n_dot_l > 0.0 ? Shadow(p, n) : 0.0;
  vec3 ambient = mix(kGroundAmbient, kSkyAmbient, 0.5 + 0.5 * n.z);
  vec3 half_vector = normalize(u_light_direction + view);
  float shininess = (u_flags & 1) != 0 ? 16.0 : 48.0;
  float specular = (u_flags & 1) != 0 ? 0.05 : 0.25;
  specular *= pow(max(dot(n, half_vector), 0.0), shininess) * n_dot_l;
  // a soft light from the eye keeps faces turned away from the sun readable
  float fill = 0.18 * max(dot(n, view), 0.0);
  vec3 color = base * (ambient + fill + kSunColor * n_dot_l * shadow) + kSunColor * specular * shadow;
  if ((u_flags & 2) != 0) {
    float rim = pow(1.0 - max(dot(n, view), 0.0), 2.0);
    color = mix(color, ToLinear(kSelectedTint), 0.35) + ToLinear(kSelectedTint) * rim * 0.6;
  }
  float haze = smoothstep(u_haze_range.x, u_haze_range.y, length(u_eye - p));
  color = mix(color, ToLinear(u_haze_color), haze * 0.85);
  frag_color = vec4(ToSrgb(color), u_color.a);
}
