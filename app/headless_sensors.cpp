// SPDX-License-Identifier: MIT
#include "app/headless_sensors.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include "core/render/render_mesh_cache.h"
#include "core/render/scene_extract.h"
#include "core/render/world_poses.h"
#include "core/sim/simulator.h"
#include "ui/platform/image_file.h"
#include "ui/platform/osmesa_context.h"
#include "ui/render/renderer.h"
#include "ui/render/sensor_camera.h"

namespace lamina::app {

namespace {

bool HasCameras(const core::Simulator& simulator) {
  for (int r = 0; r < simulator.robot_count(); ++r) {
    if (simulator.sensors(r).has_images()) return true;
  }
  return false;
}

int IntSetting(const core::Sensor& sensor, const char* key) {
  std::string text;
  sensor.GetSetting(key, &text);
  return std::atoi(text.c_str());
}

// the colour measurements (0xRRGGBB, top row first) as RGBA rows bottom-up
std::vector<std::uint8_t> BottomUpRgba(const std::vector<double>& m, int w, int h) {
  std::vector<std::uint8_t> rgba(static_cast<size_t>(w) * h * 4, 255);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const auto v = static_cast<std::uint32_t>(m[static_cast<size_t>(y) * w + x]);
      std::uint8_t* p = &rgba[4 * (static_cast<size_t>(h - 1 - y) * w + x)];
      p[0] = (v >> 16) & 0xff;
      p[1] = (v >> 8) & 0xff;
      p[2] = v & 0xff;
    }
  }
  return rgba;
}

// 16-bit binary PGM (big-endian samples), millimetres, 65535 for far or missing
bool WriteDepthPgm(const std::string& path, const double* depth, int w, int h, double zmax) {
  std::ofstream out(path, std::ios::binary);
  out << "P5\n" << w << " " << h << "\n65535\n";
  for (size_t i = 0; i < static_cast<size_t>(w) * h; ++i) {
    const double mm = depth[i] >= zmax ? 65535.0 : std::round(1000.0 * depth[i]);
    const auto v = static_cast<std::uint16_t>(std::max(0.0, std::min(65535.0, mm)));
    const char bytes[2] = {static_cast<char>(v >> 8), static_cast<char>(v & 0xff)};
    out.write(bytes, 2);
  }
  return static_cast<bool>(out);
}

}  // namespace

struct SensorCameras::State {
  core::Simulator* simulator = nullptr;
  ui::OsmesaContext context;
  ui::Renderer renderer;
  core::RenderMeshCache meshes;
  std::unique_ptr<ui::SceneCamera> camera;
  std::string folder;
  std::vector<std::vector<double>> seen;  ///< per robot, per sensor: the next time last seen
  std::vector<std::vector<int>> counts;   ///< pictures written per sensor
  int observer = -1;
  int failures = 0;
  std::string first_failure;

  void WriteNew();
  void Write(int robot, int sensor);
};

SensorCameras::SensorCameras() : state_(std::make_unique<State>()) {}

SensorCameras::~SensorCameras() {
  if (state_->simulator && state_->observer >= 0) {
    state_->simulator->RemoveStepObserver(state_->observer);
  }
  if (state_->simulator) state_->simulator->SetCameraRenderer(nullptr);
}

bool SensorCameras::Open(core::Simulator* simulator, const std::string& folder,
                         std::string* error) {
  State& s = *state_;
  if (!HasCameras(*simulator)) return true;  // a simulation without cameras never touches GL
  if (!s.context.Create(1, 1, error) || !s.renderer.Initialize(error)) return false;
  s.renderer.settings().samples = 1;
  s.simulator = simulator;
  s.camera = std::make_unique<ui::SceneCamera>(
      &s.renderer,
      [&s](core::RenderScene* scene) {
        core::ExtractScene(s.simulator->world(), core::CurrentPoses(*s.simulator), {}, {},
                           &s.meshes, scene);
      },
      [&s] { s.context.MakeCurrent(); });
  simulator->SetCameraRenderer(s.camera.get());
  if (folder.empty()) return true;
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) return *error = "cannot create " + folder + ": " + ec.message(), false;
  s.folder = folder;
  for (int r = 0; r < simulator->robot_count(); ++r) {
    s.seen.emplace_back(simulator->sensors(r).size(), -1.0);
    s.counts.emplace_back(simulator->sensors(r).size(), 0);
  }
  s.observer = simulator->AddStepObserver([&s](const core::StepEvent&) { s.WriteNew(); });
  return true;
}

// every camera whose next time moved on took a picture at the start of this step
void SensorCameras::State::WriteNew() {
  for (int r = 0; r < simulator->robot_count(); ++r) {
    const core::RobotSensors& sensors = simulator->sensors(r);
    for (int i = 0; i < sensors.size(); ++i) {
      if (!core::IsImageSensor(sensors.sensor(i)) || sensors.next_time(i) == seen[r][i]) continue;
      seen[r][i] = sensors.next_time(i);
      Write(r, i);
    }
  }
}

void SensorCameras::State::Write(int robot, int index) {
  const core::Sensor& sensor = simulator->sensors(robot).sensor(index);
  const int w = IntSetting(sensor, "xres"), h = IntSetting(sensor, "yres");
  const std::vector<double>& m = sensor.measurements();
  const size_t n = static_cast<size_t>(w) * h;
  char number[16];
  std::snprintf(number, sizeof(number), "_%04d", counts[robot][index]++);
  const std::string stem =
      folder + "/" + simulator->world().robots[robot].name + "_" + sensor.name() + number;
  const bool rgb = IntSetting(sensor, "rgb") != 0, depth = IntSetting(sensor, "depth") != 0;
  std::string zmax;
  sensor.GetSetting("zmax", &zmax);
  bool ok = m.size() >= n * ((rgb ? 1 : 0) + (depth ? 1 : 0));
  if (ok && rgb) ok = ui::WritePngBottomUp(stem + ".png", w, h, BottomUpRgba(m, w, h));
  if (ok && depth) {
    ok =
        WriteDepthPgm(stem + "_depth.pgm", m.data() + (rgb ? n : 0), w, h, std::atof(zmax.c_str()));
  }
  if (ok) return;
  if (failures++ == 0) first_failure = stem;
}

int SensorCameras::pictures() const {
  return state_->camera ? state_->camera->pictures() : 0;
}
int SensorCameras::failures() const {
  return state_->failures;
}
const std::string& SensorCameras::first_failure() const {
  return state_->first_failure;
}

}  // namespace lamina::app
