// SPDX-License-Identifier: MIT
// Where the programs find Lamina's worlds: <prefix>/share/lamina/worlds beside an installed
// program (make install), else the source tree's worlds/ (LAMINA_WORLDS_DIR).
#pragma once

#include <string>

namespace lamina::app {

std::string WorldsDir();

}  // namespace lamina::app
