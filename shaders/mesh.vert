// SPDX-License-Identifier: MIT
// Lit meshes: positions to clip space, world position and normal for the fragment stage.
#version 330 core

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_model;
uniform mat3 u_normal_matrix;
uniform mat4 u_view_projection;

out vec3 v_world_position;
out vec3 v_world_normal;

void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_world_position = world.xyz;
  v_world_normal = u_normal_matrix * a_normal;
  gl_Position = u_view_projection * world;
}
