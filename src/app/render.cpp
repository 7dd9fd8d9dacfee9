#include "app/render.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <vector>

#include "app/exit_codes.hpp"

namespace ryushi {

int render_command(const RenderOptions& o) {
  // Debian's interpreter: its python3-matplotlib, -h5py and -numpy serve it (not a pyenv one).
  const std::string python = "/usr/bin/python3";
  const std::filesystem::path script = std::filesystem::path(RYUSHI_TOOLS_DIR) / "render.py";
  if (!std::filesystem::exists(script)) {
    std::fprintf(stderr, "ryushi render: %s is missing (render needs the source tree ryushi was built from)\n",
                 script.c_str());
    return kExitInternal;
  }
  std::vector<std::string> args{python, script.string(), o.out_dir, "--field", o.field, "--frames", o.frames};
  if (o.movie) args.push_back("--movie");
  // FLAG=VALUE in one argument: a range that starts below zero ("-2e4,2e4", a pressure) would
  // otherwise read to argparse as an option of its own.
  for (auto [flag, value] : {std::pair{"--slice", &o.slice}, {"--range", &o.range}, {"--dest", &o.dest}})
    if (!value->empty()) args.push_back(std::string(flag) + "=" + *value);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(nullptr);
  pid_t child = fork();
  if (child == 0) {
    execv(python.c_str(), argv.data());
    std::fprintf(stderr, "ryushi render: cannot run %s (install Debian's python3: `make py-deps`)\n", python.c_str());
    _exit(kExitInternal);
  }
  int status = 0;
  if (child < 0 || waitpid(child, &status, 0) < 0) return kExitInternal;
  return WIFEXITED(status) ? WEXITSTATUS(status) : kExitInternal;
}

}  // namespace ryushi
