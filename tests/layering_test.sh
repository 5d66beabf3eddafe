#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The layering of the README's layout table, checked on every project #include:
#  - core/ includes no GL, GLFW, EGL, ImGui or OSMesa header, ui/render no GLFW or ImGui header;
#  - every folder includes only the folders below it (the rules table below; "core" is the
#    files at the top of core/: math types, diagnostics, numbers as text).
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

# folder: the folders it may include (besides itself)
declare -A allowed=(
  [core]=""
  [core/geometry]="core"
  [core/model]="core core/geometry"
  [core/robot]="core core/geometry core/model"
  [core/contact]="core core/geometry core/model"
  [core/control]="core core/geometry core/model core/robot"
  [core/sensors]="core core/geometry core/model core/robot"
  [core/io]="core core/geometry core/model core/control core/sensors"
  [core/sim]="core core/geometry core/model core/contact core/control core/robot core/sensors"
  [core/render]="core core/geometry core/model core/contact core/control core/robot core/sensors core/sim"
  [core/edit]="core core/geometry core/model core/io core/contact core/control core/robot core/sensors core/sim"
  [core/batch]="core core/geometry core/model core/io core/contact core/control core/robot core/sensors core/sim"
  [core/accuracy]="core core/geometry core/model core/io core/contact core/control core/robot core/sensors core/sim"
  [ui/platform]="core"
  [ui/render]="core core/geometry core/model core/render core/sensors ui/platform"
  [ui/widgets]=""
  [ui/panels]="core core/geometry core/model core/io core/contact core/control core/robot core/sensors core/sim core/render core/edit ui/viewer ui/widgets"
  [ui/viewer]="core core/geometry core/model core/io core/contact core/control core/robot core/sensors core/sim core/render core/edit ui/platform ui/render ui/panels ui/widgets"
  [app]="core core/geometry core/model core/io core/contact core/control core/robot core/sensors core/sim core/render core/edit core/batch core/accuracy ui/platform ui/render ui/viewer ui/widgets"
)

# the folder of a project path: core/x/y.h -> core/x, core/y.h -> core, app/z.cpp -> app (and
# app/python/z.cpp -> app: the Python bindings are thin mains too)
folder_of() {
  local path=$1 first rest second
  first=${path%%/*}
  rest=${path#*/}
  if [ "$first" = app ] || [ "$rest" = "${rest#*/}" ]; then
    echo "$first"
  else
    second=${rest%%/*}
    echo "$first/$second"
  fi
}

layer_errors=0
while IFS= read -r line; do
  file=${line%%:*}
  file=${file#"$root"/}
  included=$(sed -nE 's/.*#[[:space:]]*include[[:space:]]*"([^"]+)".*/\1/p' <<<"$line")
  case $included in core/* | ui/* | app/*) ;; *) continue ;; esac
  from=$(folder_of "$file")
  to=$(folder_of "$included")
  [ "$from" = "$to" ] && continue
  if [ -z "${allowed[$from]+set}" ]; then
    echo "$file: folder '$from' has no layering rule (add it to tests/layering_test.sh and the README)"
    layer_errors=$((layer_errors + 1))
    continue
  fi
  case " ${allowed[$from]} " in
    *" $to "*) ;;
    *)
      echo "$file: '$from' may not include '$included' ('$to' is not below it)"
      layer_errors=$((layer_errors + 1))
      ;;
  esac
done < <(grep -rnE '#[[:space:]]*include[[:space:]]*"(core|ui|app)/' "$root/core" "$root/ui" "$root/app" \
  --include='*.h' --include='*.cpp')
if [ $layer_errors -gt 0 ]; then
  echo "$layer_errors include(s) break the layering"
  status=1
fi
[ $status -eq 0 ] && echo "layering ok: core/ is free of GL, GLFW, EGL, ImGui and OSMesa; every folder includes only the folders below it"
exit $status
