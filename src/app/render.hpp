#pragma once
// `ryushi render OUT ...`: runs tools/render.py (Debian's Python with matplotlib, h5py and
// ffmpeg) on a run's frames. The script lives in the source tree the binary was built from.
#include <string>

namespace ryushi {

struct RenderOptions {
  std::string out_dir, field = "pressure", frames = "all", slice, range, dest;
  bool movie = false;
};

// The script's exit code (0 done, 2 bad input, 1 internal error or a missing interpreter).
int render_command(const RenderOptions& options);

}  // namespace ryushi
