#include "app/sweep.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <spdlog/spdlog.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>

#include "app/exit_codes.hpp"
#include "app/plugins.hpp"
#include "io/atomic_file.hpp"
#include "scene/scene.hpp"

extern char** environ;

namespace ryushi {

namespace fs = std::filesystem;

std::pair<std::string, std::vector<std::string>> parse_vary(const std::string& vary) {
  auto eq = vary.find('=');
  if (eq == std::string::npos || eq == 0)
    throw std::invalid_argument("--vary " + vary + ": expected section.key=v1,v2,...");
  std::string key = vary.substr(0, eq), rest = vary.substr(eq + 1);
  std::vector<std::string> values;
  std::string current;
  int depth = 0;
  for (char c : rest) {
    if (c == '[') ++depth;
    if (c == ']') --depth;
    if (c == ',' && depth == 0) {
      values.push_back(current);
      current.clear();
    } else {
      current += c;
    }
  }
  values.push_back(current);
  for (auto& v : values)
    if (v.empty()) throw std::invalid_argument("--vary " + vary + ": an empty value");
  return {key, values};
}

namespace {

// Ctrl-C (SIGINT) or SIGTERM: no new run starts, the running ones are told to stop (they write
// their checkpoint, exit 130), sweep.csv is written for what finished, and the sweep exits 130.
// Before, the sweep died at once without its table (or, where its runs did not see the signal,
// counted the stopped run as failed and started the next).
volatile std::sig_atomic_t g_sweep_interrupted = 0;
extern "C" void on_sweep_signal(int) {
  g_sweep_interrupted = 1;
}

struct Run {
  std::vector<std::string> values;  // one per varied key
  fs::path dir;
};

// A directory name from "key=value" pairs: letters, digits and ._=- kept, the rest '_'.
std::string run_name(const std::vector<std::string>& keys, const std::vector<std::string>& values) {
  std::string name;
  for (std::size_t k = 0; k < keys.size(); ++k) name += (k ? "__" : "") + keys[k] + "=" + values[k];
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '=' && c != '-') c = '_';
  return name;
}

nlohmann::json read_json(const fs::path& p) {
  std::ifstream in(p);
  if (!in) return nullptr;
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception&) {
    return nullptr;  // a run killed while writing leaves none (atomic files), but be safe
  }
}

bool completed(const fs::path& dir) {
  auto s = read_json(dir / "summary.json");
  // A run stopped at its max_steps is as finished as it will get: kept, not run again.
  return s.is_object() && (s.value("status", "") == "completed" || s.value("status", "") == "max_steps");
}

pid_t spawn_run(const std::string& self, const std::vector<std::string>& args, const fs::path& log) {
  std::vector<std::string> all{self};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = -1;
  int rc = posix_spawn(&pid, self.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("cannot start " + self);
  return pid;
}

std::string csv_field(const nlohmann::json& v) {
  if (v.is_number()) {
    char b[32];
    std::snprintf(b, sizeof b, "%.10g", v.get<double>());
    return b;
  }
  if (v.is_string()) return v.get<std::string>();
  return "";
}

std::string quoted(std::string s) {
  if (s.find_first_of(",\"") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

int run_sweep(const SweepOptions& o) {
  std::vector<std::string> keys;
  std::vector<std::vector<std::string>> choices;
  try {
    if (o.vary.empty()) throw std::invalid_argument("give at least one --vary section.key=v1,v2,...");
    for (auto& v : o.vary) {
      auto [key, values] = parse_vary(v);
      keys.push_back(key);
      choices.push_back(values);
    }
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "ryushi sweep: %s\n", e.what());
    return kExitBadInput;
  }
  // The cartesian product, the last key varying fastest.
  std::vector<Run> runs{{{}, {}}};
  for (auto& values : choices) {
    std::vector<Run> next;
    for (auto& r : runs)
      for (auto& v : values) {
        Run n = r;
        n.values.push_back(v);
        next.push_back(n);
      }
    runs.swap(next);
  }
  const fs::path out = o.out_dir;
  for (auto& r : runs) r.dir = out / run_name(keys, r.values);
  // Every combination must load before anything runs: a typo fails now, not after hours.
  try {
    load_plugins(o.plugins, o.scene);
  } catch (const SceneError& e) {
    std::fprintf(stderr, "ryushi sweep: %s\n", e.what());
    return kExitBadInput;
  }
  for (auto& r : runs) {
    std::vector<std::string> sets = o.sets;
    for (std::size_t k = 0; k < keys.size(); ++k) sets.push_back(keys[k] + "=" + r.values[k]);
    try {
      load_scene(o.scene, sets);
    } catch (const SceneError& e) {
      std::fprintf(stderr, "ryushi sweep: %s\n", e.what());
      return kExitBadInput;
    }
  }
  try {
    fs::create_directories(out);
  } catch (const fs::filesystem_error& e) {
    std::fprintf(stderr, "ryushi sweep: could not write the output: %s\n", e.what());
    return kExitOutputFailed;
  }
  const std::string self = fs::read_symlink("/proc/self/exe").string();
  std::size_t kept = 0, next = 0, failed = 0;
  std::map<pid_t, std::size_t> active;
  // Without SA_RESTART (std::signal's glibc default), so that the signal ends the wait() below.
  struct sigaction stop {
  }, old_int{}, old_term{};
  stop.sa_handler = on_sweep_signal;
  sigemptyset(&stop.sa_mask);
  sigaction(SIGINT, &stop, &old_int);
  sigaction(SIGTERM, &stop, &old_term);
  g_sweep_interrupted = 0;
  bool told_to_stop = false;
  auto start_next = [&] {
    if (g_sweep_interrupted) return false;
    while (next < runs.size() && completed(runs[next].dir)) ++next, ++kept;
    if (next >= runs.size()) return false;
    auto& r = runs[next++];
    fs::create_directories(r.dir);
    std::vector<std::string> args{"run",     o.scene,       "--out",     r.dir.string(),
                                  "--quiet", "--overwrite", "--threads", std::to_string(o.threads)};
    for (auto& s : o.sets) args.insert(args.end(), {"--set", s});
    for (auto& p : o.plugins) args.insert(args.end(), {"--plugin", p});
    for (std::size_t k = 0; k < keys.size(); ++k)
      args.insert(args.end(), {"--set", keys[k] + "=" + r.values[k]});
    active[spawn_run(self, args, r.dir / "log.txt")] = std::size_t(&r - runs.data());
    return true;
  };
  for (int j = 0; j < std::max(1, o.jobs); ++j) start_next();
  while (!active.empty()) {
    int status = 0;
    pid_t pid = ::wait(&status);
    if (g_sweep_interrupted && !told_to_stop) {
      // A terminal's Ctrl-C reaches the runs too; a signal to the sweep alone is passed on.
      for (auto& [child, index] : active) ::kill(child, SIGINT);
      told_to_stop = true;
    }
    if (pid < 0 && errno == EINTR) continue;
    if (pid < 0) break;
    auto it = active.find(pid);
    if (it == active.end()) continue;
    auto& r = runs[it->second];
    active.erase(it);
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (code == kExitInterrupted) g_sweep_interrupted = 1;  // stopped by a signal of its own
    if (code != kExitDone && code != kExitInterrupted) ++failed;
    if (!o.quiet)
      spdlog::info("sweep: {} {} (exit {})", r.dir.filename().string(),
                   code == kExitDone          ? "done"
                   : code == kExitInterrupted ? "interrupted"
                                              : "FAILED",
                   code);
    start_next();
  }
  sigaction(SIGINT, &old_int, nullptr);
  sigaction(SIGTERM, &old_term, nullptr);
  if (!o.quiet && kept)
    spdlog::info("sweep: {} of {} runs were already complete and kept", kept, runs.size());

  // sweep.csv: one row per run.
  std::vector<nlohmann::json> summaries, profiles;
  std::set<std::string> metric_names, diag_names, system_names;
  for (auto& r : runs) {
    summaries.push_back(read_json(r.dir / "summary.json"));
    profiles.push_back(read_json(r.dir / "profile.json"));
    for (const char* section : {"metrics", "diagnostics"})
      if (summaries.back().is_object() && summaries.back().contains(section))
        for (auto& [k, v] : summaries.back()[section].items())
          if (v.is_number()) (section[0] == 'm' ? metric_names : diag_names).insert(k);
    if (profiles.back().is_object() && profiles.back().contains("systems"))
      for (auto& s : profiles.back()["systems"]) system_names.insert(s.value("name", ""));
  }
  std::ostringstream csv;
  for (auto& k : keys) csv << quoted(k) << ",";
  csv << "run,status,wall_time_s,steps,particles,particle_steps_per_second";
  for (auto& m : metric_names) csv << "," << m;
  for (auto& d : diag_names) csv << "," << d;
  for (auto& s : system_names) csv << ",share_" << s;
  csv << "\n";
  for (std::size_t i = 0; i < runs.size(); ++i) {
    for (auto& v : runs[i].values) csv << quoted(v) << ",";
    const auto& s = summaries[i];
    csv << runs[i].dir.filename().string() << ",";
    if (!s.is_object()) {
      csv << "missing,,,,";
      for (std::size_t k = 0; k < metric_names.size() + diag_names.size() + system_names.size(); ++k)
        csv << ",";
      csv << "\n";
      continue;
    }
    csv << csv_field(s.value("status", nlohmann::json())) << ","
        << csv_field(s.value("wall_time_s", nlohmann::json())) << ","
        << csv_field(s.value("steps", nlohmann::json())) << ","
        << csv_field(s.value("particles", nlohmann::json())) << ","
        << csv_field(s.value("particle_steps_per_second", nlohmann::json()));
    for (auto& m : metric_names)
      csv << "," << (s.contains("metrics") ? csv_field(s["metrics"].value(m, nlohmann::json())) : "");
    for (auto& d : diag_names)
      csv << "," << (s.contains("diagnostics") ? csv_field(s["diagnostics"].value(d, nlohmann::json())) : "");
    for (auto& name : system_names) {
      std::string share;
      if (profiles[i].is_object())
        for (auto& sys : profiles[i]["systems"])
          if (sys.value("name", "") == name) share = csv_field(sys.value("share", nlohmann::json()));
      csv << "," << share;
    }
    csv << "\n";
  }
  try {
    write_text_atomic(out / "sweep.csv", csv.str());
  } catch (const OutputError& e) {
    std::fprintf(stderr, "ryushi sweep: could not write the output: %s\n", e.what());
    return kExitOutputFailed;
  }
  // sweep.png with Debian's python3 and matplotlib, if present.
  const fs::path script = fs::path(RYUSHI_TOOLS_DIR) / "plot_sweep.py";
  std::string cmd = "/usr/bin/python3 '" + script.string() + "' '" + (out / "sweep.csv").string() + "' '" +
                    (out / "sweep.png").string() + "'";
  for (auto& k : keys) cmd += " --key '" + k + "'";
  if (!o.error.empty()) cmd += " --error '" + o.error + "'";
  if (std::system((cmd + (o.quiet ? " > /dev/null 2>&1" : "")).c_str()) != 0)
    std::fprintf(stderr,
                 "ryushi sweep: no sweep.png (needs Debian's python3-matplotlib: `make py-deps`, and an "
                 "error column)\n");
  if (!o.quiet)
    std::printf("sweep: %zu runs, %zu failed%s -> %s\n", runs.size(), failed,
                g_sweep_interrupted ? ", interrupted (run it again to go on)" : "",
                (out / "sweep.csv").string().c_str());
  if (g_sweep_interrupted) return kExitInterrupted;
  return failed ? kExitNumericalFailure : kExitDone;
}

}  // namespace ryushi
