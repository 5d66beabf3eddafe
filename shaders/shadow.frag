// SPDX-License-Identifier: MIT
// Shadow map pass: depth only.
#version 330 core

void main() {}
