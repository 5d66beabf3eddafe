// SPDX-License-Identifier: MIT
// `lamina-headless record WORLD --duration T --fps N -o DIR|FILE.mp4`: frames at simulation
// times k/N for k = 0..floor(T*N), through ffmpeg into an .mp4 when ffmpeg is on PATH, otherwise
// as DIR/frame_00000.png, ... (an .mp4 name then falls back to the directory NAME_frames).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

#include <unistd.h>

#include "app/headless_render.h"
#include "app/headless_render_commands.h"
#include "core/render/overlay_options.h"
#include "core/sim/simulator.h"
#include "ui/platform/image_file.h"

namespace lamina::app {

namespace {

struct RecordOptions {
  std::string world;
  std::string output;
  double duration = 0.0;
  double fps = 30.0;
  std::string size = "1280x720";
  std::string camera;
  std::string overlay;
  int samples = 4;
};

bool EndsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool FfmpegOnPath() {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return false;
  std::istringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (!dir.empty() && access((dir + "/ffmpeg").c_str(), X_OK) == 0) return true;
  }
  return false;
}

// `\r[#########           ] 45% frame 12/27` on stderr
void ShowProgress(int done, int total) {
  constexpr int kWidth = 30;
  const int filled = total > 0 ? done * kWidth / total : kWidth;
  std::string bar(filled, '#');
  bar.resize(kWidth, ' ');
  std::cerr << "\r[" << bar << "] " << (total > 0 ? done * 100 / total : 100) << "% frame " << done
            << "/" << total << std::flush;
  if (done == total) std::cerr << "\n";
}

// where frames go: an ffmpeg pipe or PNG files in a directory
class FrameSink {
 public:
  ~FrameSink() {
    if (pipe_ != nullptr) pclose(pipe_);
  }

  bool Open(const RecordOptions& options, const ViewOptions& view, std::string* error) {
    width_ = view.width;
    height_ = view.height;
    directory_ = options.output;
    if (EndsWith(options.output, ".mp4")) {
      if (FfmpegOnPath()) return OpenFfmpeg(options, error);
      directory_ = options.output.substr(0, options.output.size() - 4) + "_frames";
      std::cerr << "lamina-headless record: ffmpeg is not on PATH; writing PNG frames to "
                << directory_ << "/ instead of " << options.output << "\n";
    }
    std::error_code code;
    std::filesystem::create_directories(directory_, code);
    if (code) {
      *error = "cannot create directory " + directory_ + ": " + code.message();
      return false;
    }
    return true;
  }

  bool Write(int index, const std::vector<std::uint8_t>& pixels) {
    if (pipe_ != nullptr) {
      return std::fwrite(pixels.data(), 1, pixels.size(), pipe_) == pixels.size();
    }
    char name[32];
    std::snprintf(name, sizeof(name), "/frame_%05d.png", index);
    return ui::WritePngBottomUp(directory_ + name, width_, height_, pixels);
  }

  /// False when ffmpeg reported a failure.
  bool Close() {
    if (pipe_ == nullptr) return true;
    const int status = pclose(pipe_);
    pipe_ = nullptr;
    return status == 0;
  }

  std::string destination() const { return pipe_ != nullptr ? output_ : directory_ + "/"; }

 private:
  bool OpenFfmpeg(const RecordOptions& options, std::string* error) {
    output_ = options.output;
    std::ostringstream command;
    // rows arrive bottom-up from OpenGL: vflip
    command << "ffmpeg -y -loglevel error -f rawvideo -pix_fmt rgba -s " << width_ << "x" << height_
            << " -r " << options.fps << " -i - -vf vflip -pix_fmt yuv420p '" << options.output
            << "'";
    pipe_ = popen(command.str().c_str(), "w");
    if (pipe_ == nullptr) *error = "cannot start ffmpeg";
    return pipe_ != nullptr;
  }

  FILE* pipe_ = nullptr;
  int width_ = 0, height_ = 0;
  std::string directory_, output_;
};

int RunRecord(const RecordOptions& options) {
  ViewOptions view;
  std::string error;
  if (!core::ParseViewOptions(options.size, options.camera, options.overlay, &view, &error)) {
    std::cerr << "lamina-headless record: " << error << "\n";
    return 2;
  }
  view.samples = options.samples;
  if (options.output.find('\'') != std::string::npos) {
    std::cerr << "lamina-headless record: -o must not contain a quote (')\n";
    return 2;
  }
  core::WorldDesc world;
  if (!LoadWorldForRendering(options.world, &world)) {
    std::cerr << "lamina-headless record: cannot load world '" << options.world << "'\n";
    return 1;
  }
  OffscreenView renderer;
  FrameSink sink;
  if (!renderer.Open(view, &error) || !sink.Open(options, view, &error)) {
    std::cerr << "lamina-headless record: " << error << "\n";
    return 1;
  }
  std::unique_ptr<core::Simulator> simulator = MakeRenderSimulator(world);
  const int last = static_cast<int>(std::floor(options.duration * options.fps + 1e-9));
  for (int k = 0; k <= last; ++k) {
    const double time = k / options.fps;
    if (time > simulator->time()) simulator->Simulate(time - simulator->time());
    if (!sink.Write(k, renderer.Render(world, core::CurrentPoses(*simulator), simulator.get()))) {
      std::cerr << "\nlamina-headless record: cannot write frame " << k << "\n";
      return 1;
    }
    ShowProgress(k + 1, last + 1);
  }
  const std::string destination = sink.destination();
  if (!sink.Close()) {
    std::cerr << "lamina-headless record: ffmpeg failed writing " << options.output << "\n";
    return 1;
  }
  std::cout << "wrote " << last + 1 << " frames (" << view.width << "x" << view.height << ", "
            << options.fps << " fps, t = 0.." << last / options.fps << " s) to " << destination
            << "\n";
  return 0;
}

}  // namespace

Subcommand AddRecordCommand(CLI::App& app) {
  auto options = std::make_shared<RecordOptions>();
  CLI::App* record =
      app.add_subcommand("record", "simulate and render frames in simulation time (OSMesa)");
  record->add_option("world", options->world, "world file")->required();
  record
      ->add_option("-o,--output", options->output,
                   "directory for frame_00000.png..., or FILE.mp4 (needs ffmpeg on PATH)")
      ->required();
  record->add_option("--duration", options->duration, "simulated time, s")
      ->required()
      ->check(CLI::NonNegativeNumber);
  record->add_option("--fps", options->fps, "frames per simulated second (default 30)")
      ->check(CLI::PositiveNumber);
  record->add_option("--size", options->size, "image size WIDTHxHEIGHT (default 1280x720)");
  record->add_option("--camera", options->camera,
                     "world (default), bodies, or 'target=x,y,z;yaw=deg;pitch=deg;dist=m;fov=deg'");
  record->add_option("--overlay", options->overlay,
                     "comma list of " + core::OverlayNames() + " (or all)");
  record
      ->add_option("--msaa", options->samples,
                   "antialiasing samples per pixel: 1 (off) or 4 (default)")
      ->check(CLI::IsMember({1, 4}));
  return {record, [options] { return RunRecord(*options); }};
}

}  // namespace lamina::app
