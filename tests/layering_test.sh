#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Fails when core/ includes GL, GLFW, EGL, ImGui or OSMesa headers, or ui/render includes
# GLFW or ImGui: the core must build and run without any of them.
set -u
root=${1:?usage: layering_test.sh PROJECT_ROOT}
status=0
if hits=$(grep -rnE '#[[:space:]]*include[[:space:]]*[<"](GL/|GLFW/|EGL/|glad/|imgui|backends/imgui|OSMesa|GL/osmesa)' \
    "$root/core"); then
  echo "core/ must not include GL, GLFW, EGL, ImGui or OSMesa headers:"
  echo "$hits"
  status=1
fi
if [ -d "$root/ui/render" ] &&
   hits=$(grep -rnE '#[[:space:]]*include[[:space:]]*[<"](GLFW/|imgui|backends/imgui)' "$root/ui/render"); then
  echo "ui/render must not include GLFW or ImGui headers:"
  echo "$hits"
  status=1
fi
[ $status -eq 0 ] && echo "layering ok: core/ is free of GL, GLFW, EGL, ImGui and OSMesa"
exit $status
