# SPDX-License-Identifier: MIT
# Every third-party package Lamina uses, all from Debian (see cmake/setup-deps.sh).

find_package(PkgConfig REQUIRED)
find_package(Eigen3 3.4 REQUIRED CONFIG)
pkg_check_modules(ODE REQUIRED IMPORTED_TARGET ode)
find_package(fcl 0.7 REQUIRED CONFIG)
find_package(assimp 5.2 REQUIRED CONFIG)
find_package(urdfdom REQUIRED CONFIG)
find_package(tinyxml2 REQUIRED CONFIG)
find_package(nlohmann_json 3.10 REQUIRED CONFIG)
find_package(CLI11 REQUIRED CONFIG)

if(LAMINA_BUILD_EDITOR)
  find_package(glfw3 3.3 REQUIRED CONFIG)
  set(OpenGL_GL_PREFERENCE GLVND)
  find_package(OpenGL REQUIRED COMPONENTS OpenGL)
endif()
if(LAMINA_BUILD_EDITOR OR LAMINA_BUILD_HEADLESS)
  pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)
  pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
endif()
# OSMesa: off-screen GL for lamina-headless, the golden-image tests and the render benchmark
# (libosmesa6-dev); never linked into a program that also links libGL/libOpenGL
if(LAMINA_BUILD_HEADLESS)
  pkg_check_modules(OSMESA REQUIRED IMPORTED_TARGET osmesa)
endif()
if(LAMINA_BUILD_TESTS)
  find_package(GTest REQUIRED CONFIG)
endif()
if(LAMINA_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED CONFIG)
endif()
