// SPDX-License-Identifier: MIT
// Background: a vertical sky gradient, pale haze at the bottom of the screen to blue at the top,
// with a slight tilt by the camera pitch so that looking up shows more sky.
#version 330 core

in vec2 v_ndc;

uniform vec3 u_top_color;
uniform vec3 u_bottom_color;
uniform float u_pitch_shift;  // added to the gradient position, from the camera pitch

out vec4 frag_color;

void main() {
  float t = clamp(0.5 * v_ndc.y + 0.5 + u_pitch_shift, 0.0, 1.0);
  frag_color = vec4(mix(u_bottom_color, u_top_color, smoothstep(0.0, 1.0, t)), 1.0);
}
