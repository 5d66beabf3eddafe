// SPDX-License-Identifier: MIT
// --trace FILE: one JSON object per drawn frame (JSON Lines) with what scripted UI tests check —
// time, play state, selection and tool, the drag (body, force, target, effective mass), the
// sampled body's velocity and contacts (the blended values its inspector shows), every object's
// position, every robot's joint values, the undo labels, unsaved changes, the last message and the
// panels' named items (item_registry.h: where each field is and what it shows). Written and flushed
// frame by frame so a test can read it while the editor runs.
#pragma once

#include <fstream>
#include <string>

#include "ui/viewer/live_session.h"
#include "ui/viewer/viewer_state.h"

namespace lamina::ui {

class FrameTrace {
 public:
  /// False with `error` naming the path when it cannot be written.
  bool Open(const std::string& path, std::string* error);
  /// One line for this frame (nothing when not open).
  void Write(const SessionFrame& frame, const ViewerState& state);

 private:
  std::ofstream out_;
  long frames_ = 0;
};

}  // namespace lamina::ui
