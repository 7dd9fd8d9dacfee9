#pragma once
// How a fuzzer input maps to a scene load (shared by fuzz/scene_fuzzer.cpp and the corpus replay
// in tests/fuzz_corpus_test.cpp): the text is the scene file; its leading lines
// "#set section.key=value" are --set overrides. The outcome is "ok", or the SceneError's message,
// which must name a place: it starts with the scene's path and ':' or with "--set ".
#include <fstream>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace ryushi::fuzz {

struct SceneInput {
  std::string text;
  std::vector<std::string> overrides;
};

inline SceneInput split_input(const std::string& input) {
  SceneInput in{input, {}};
  std::size_t at = 0;
  while (input.compare(at, 5, "#set ") == 0) {
    std::size_t end = input.find('\n', at);
    if (end == std::string::npos) end = input.size();
    in.overrides.push_back(input.substr(at + 5, end - at - 5));
    at = end < input.size() ? end + 1 : end;
  }
  return in;
}

struct Outcome {
  bool accepted = false;
  std::string message;  // the SceneError's, when rejected
  bool names_a_place = true;
};

// Writes the scene to `path` and loads it. Exceptions other than SceneError propagate.
inline Outcome load(const std::string& input, const std::string& path) {
  auto in = split_input(input);
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << in.text;
  }
  Outcome o;
  try {
    load_scene(path, in.overrides);
    o.accepted = true;
  } catch (const SceneError& e) {
    o.message = e.what();
    o.names_a_place = o.message.rfind(path + ":", 0) == 0 || o.message.rfind("--set ", 0) == 0;
  }
  return o;
}

}  // namespace ryushi::fuzz
