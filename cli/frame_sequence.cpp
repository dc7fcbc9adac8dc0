#include "cli/frame_sequence.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "cli/outputs.h"
#include "io/image_output.h"
#include "util/atomic_file.h"
#include "util/errors.h"
#include "util/temp_files.h"

namespace phellem {

void check_frame_outputs(const cli::Options& o) {
  size_t n = 0;
  for (size_t i = 0; i + 1 < o.exr.size(); ++i)
    if (o.exr[i] == '%') {
      if (o.exr[i + 1] == '%') {
        ++i;
        continue;
      }
      ++n;
      size_t j = i + 1;
      while (j < o.exr.size() && std::isdigit(static_cast<unsigned char>(o.exr[j]))) ++j;
      if (j >= o.exr.size() || o.exr[j] != 'd') throw UserError("", "-o", "only %d-style frame fields (e.g. %04d) are allowed");
    }
  if (n != 1) throw UserError("", "-o", "the pattern needs exactly one frame field such as %04d");
  if (!o.mp4.empty() && std::system("command -v ffmpeg >/dev/null 2>&1") != 0)
    throw UserError(o.mp4, "--mp4", "ffmpeg is not installed (apt-get install ffmpeg), so no MP4 can be encoded");
}

std::string frame_name(const std::string& pattern, int frame) {
  std::vector<char> buf(pattern.size() + 64);
  std::snprintf(buf.data(), buf.size(), pattern.c_str(), frame);
  return buf.data();
}

std::string png_frame_name(const std::string& exr_frame) {
  return std::filesystem::path(exr_frame).replace_extension(".png").string();
}

void render_frame(const cli::Options& o, const Loaded& l, const RenderScene& scene, const Camera& camera, int frame, int frames,
                  OutputSet& out) {
  RenderSettings s = l.settings;
  s.progress_label = "frame " + std::to_string(frame + 1) + "/" + std::to_string(frames);
  const RenderResult res = render_image(scene, camera, l.width, l.height, s);
  const std::string exr = frame_name(o.exr, frame);
  out.write("-o", exr, [&](const std::string& tmp) { write_exr(res.film, tmp, exr_camera(camera)); });
  if (o.png_frames || !o.mp4.empty())
    out.write(png_frames_option(o), png_frame_name(exr),
              [&](const std::string& tmp) { write_png(res.film, tmp, o.view.empty() ? default_view() : o.view); });
}

void encode_mp4(const cli::Options& o, OutputSet& out) {
  // The PNG frames are still temporaries: temp_path_beside() renames only the file name's
  // stem, so applied to the pattern it gives the pattern of their temporary names.
  const std::string png_pattern = temp_path_beside(png_frame_name(o.exr));
  const std::string tmp = out.stage("--mp4", o.mp4);
  // No shell between us and ffmpeg: file names are passed as they are, whatever they hold.
  std::vector<std::string> args = {"ffmpeg",     "-loglevel", "error",   "-nostdin",  "-y",
                                   "-framerate", "24",        "-i",      png_pattern, "-c:v",
                                   "libx264",    "-pix_fmt",  "yuv420p", "-vf",       "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                                   "-f",         "mp4",       tmp};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (const int e = posix_spawnp(&pid, "ffmpeg", nullptr, nullptr, argv.data(), environ); e != 0)
    throw UserError(o.mp4, "--mp4", std::string("cannot run ffmpeg: ") + std::strerror(e));
  int status = 0;
  {
    const LiveChild child{int(pid)};  // a termination signal ends ffmpeg too
    while (waitpid(pid, &status, 0) < 0)
      if (errno != EINTR) throw UserError(o.mp4, "--mp4", std::string("lost ffmpeg: ") + std::strerror(errno));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw UserError(o.mp4, "--mp4",
                    "ffmpeg failed to encode the frames (" +
                        (WIFEXITED(status) ? "exit code " + std::to_string(WEXITSTATUS(status))
                                           : "signal " + std::to_string(WIFSIGNALED(status) ? WTERMSIG(status) : 0)) +
                        "); the frames were not written either");
}

}  // namespace phellem
