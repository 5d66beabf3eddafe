#!/bin/sh
# SPDX-License-Identifier: MIT
# Regenerates the viewer screenshots in this directory with the real `lamina` under Xvfb.
# usage: docs/screenshots/regenerate.sh BUILD_DIR   (then look at every PNG before committing)
# 4x MSAA as on a GPU (the window picks FXAA by itself on software GL)
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
