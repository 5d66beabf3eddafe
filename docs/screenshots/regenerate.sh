#!/bin/sh
# SPDX-License-Identifier: MIT
# Regenerates the viewer screenshots in this directory with the real `lamina` under Xvfb.
# usage: docs/screenshots/regenerate.sh BUILD_DIR   (then look at every PNG before committing)
# 4x MSAA as on a GPU (the window draws one sample on software GL); needs Xvfb and xdotool
set -eu
build=${1:?usage: $0 BUILD_DIR}
here=$(cd "$(dirname "$0")" && pwd)
worlds=$here/../../worlds/klampt
padded=$here/../../tests/render/data/padded_contacts.xml
shot() {  # shot NAME WORLD OPTIONS...
  name=$1 world=$2
  shift 2
  xvfb-run -a -s "-screen 0 1280x720x24" "$build/bin/lamina" "$world" --frames 6 --paused \
    --msaa 4 --screenshot "$here/$name.png" "$@" 2>/dev/null
}
shot viewer "$worlds/athlete_fractal_1.xml" --size 1280x720 --time 1 \
  --camera "target=0,0,0.6;yaw=35;pitch=22;dist=7"
shot selection "$worlds/athlete_fractal_1.xml" --size 1280x720 --time 1 --select 1 \
  --camera "target=0,0,0.6;yaw=35;pitch=22;dist=4.5" --overlay frames
shot overlay_contacts "$padded" --size 960x540 --no-ui --time 0.1 --camera bodies \
  --overlay contacts,normals,forces
shot overlay_padding "$padded" --size 960x540 --no-ui --time 0.1 --camera bodies \
  --overlay padding
shot overlay_com "$worlds/athlete_fractal_1.xml" --size 960x540 --no-ui --time 1 \
  --camera bodies --overlay com
shot overlay_frames "$worlds/athlete_fractal_1.xml" --size 960x540 --no-ui --time 1 \
  --camera bodies --overlay frames
# a world that does not load: the error in the World panel, the Open world panel expanded
shot open_world /no/such/world.xml --size 960x540 || true
shot overlay_bbox "$worlds/simulation_test_worlds/stacktest.xml" --size 960x540 --no-ui \
  --time 0.5 --camera bodies --overlay bbox

# the editor's panels, as in the golden screenshots (tests/ui/golden) but with 4x MSAA
editor=$here/../../tests/data/editor
panels() {  # panels NAME WORLD OPTIONS...: lockstep, the pointer moved off the panels
  name=$1 world=$2
  shift 2
  start_x
  DISPLAY=:$display "$build/bin/lamina" "$world" --lockstep --frames 120 --size 1280x720 \
    --msaa 4 --screenshot "$here/$name.png" "$@" 2>/dev/null &
  sleep 0.5
  DISPLAY=:$display xdotool mousemove 1279 0
  wait $!
  stop_x
}
start_x() {  # an Xvfb of its own (it picks a free display)
  Xvfb -displayfd 1 -screen 0 1280x720x24 > /tmp/lamina_shot_display 2>/dev/null &
  xvfb=$!
  while [ ! -s /tmp/lamina_shot_display ]; do sleep 0.05; done
  display=$(cat /tmp/lamina_shot_display)
}
stop_x() {
  kill $xvfb
  rm -f /tmp/lamina_shot_display
}
boxes_camera="target=0.25,0,0.1;yaw=-60;pitch=25;dist=2.2"
panels panels_inspector "$editor/two_boxes.xml" --select 1 \
  --panels simulation,world,inspector --camera "$boxes_camera"
panels panels_robot "$editor/planar_arm.xml" --select 2 --panels robot,inspector,world,open \
  --camera "target=1.7,0,1.55;yaw=-90;pitch=12;dist=5"
panels panels_settings_plots "$editor/planar_arm.xml" --select 3 \
  --panels simulation,settings,overlays,plots
panels panels_help "$editor/two_boxes.xml" --panels help --camera "$boxes_camera"

# the mouse tools on the two boxes, held in mid-drag when the screenshot is taken (the camera of
# tests/ui/editor_script_test.cpp: the left box's front face is at pixel 305, 300)
tool() {  # tool NAME FIRST "KEYS BUTTON" X Y OPTIONS...: key FIRST pressed (none: no key),
  # then KEYS held and BUTTON dragged to X, Y
  name=$1 first=$2 keys=${3% *} button=${3#* } x=$4 y=$5
  shift 5
  start_x
  DISPLAY=:$display "$build/bin/lamina" "$editor/two_boxes.xml" --lockstep --frames 100 \
    --size 800x600 --msaa 4 --camera "target=0.25,0,0.1;yaw=-90;pitch=0;dist=2" \
    --screenshot "$here/$name.png" "$@" 2>/dev/null &
  lamina=$!
  sleep 1
  if [ "$first" != none ]; then
    DISPLAY=:$display xdotool keydown "$first"
    sleep 0.15
    DISPLAY=:$display xdotool keyup "$first"
  fi
  DISPLAY=:$display xdotool mousemove 305 300
  sleep 0.2
  [ "$keys" = none ] || DISPLAY=:$display xdotool keydown "$keys"
  DISPLAY=:$display xdotool mousedown "$button"
  for step in 1 2 3 4 5 6 7 8 9 10; do
    DISPLAY=:$display xdotool mousemove $((305 + (x - 305) * step / 10)) \
      $((300 + (y - 300) * step / 10))
    sleep 0.05
  done
  wait $lamina
  stop_x
}
tool tool_force none "ctrl 3" 230 100 --no-ui
tool tool_torque none "ctrl 1" 380 250 --no-ui
tool tool_kinematic none "ctrl 2" 430 300 --no-ui
tool tool_pose g "none 1" 305 200 --no-ui --paused --select 1
