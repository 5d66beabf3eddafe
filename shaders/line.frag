// SPDX-License-Identifier: MIT
// Debug lines: flat colour, dimmed by u_alpha_scale for the see-through pass.
#version 330 core

in vec4 v_color;

uniform float u_alpha_scale;

out vec4 frag_color;

void main() { frag_color = vec4(v_color.rgb, v_color.a * u_alpha_scale); }
