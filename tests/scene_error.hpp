#pragma once
// The loader's message for a scene text, from the file name on ("" when it loads).
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "test_util.hpp"

namespace ryushi::test {

// Each call writes its own file: test cases that use it run as parallel ctest processes.
inline std::string scene_error(const std::string& text, const std::vector<std::string>& sets = {}) {
  auto path = unique_scratch("scene_errors") / "bad.toml";
  write_text(path, text);
  try {
    load_scene(path.string(), sets);
  } catch (const SceneError& e) {
    std::string msg = e.what();
    auto cut = msg.find("bad.toml");
    return cut == std::string::npos ? msg : msg.substr(cut);
  }
  return "";
}

}  // namespace ryushi::test
