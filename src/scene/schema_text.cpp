// `ryushi keys` without --markdown: every key on one line for a terminal, the first sentence of
// its meaning (it printed the Markdown of docs/scenes.md, tables and all; issue 51).
#include <cstdio>
#include <sstream>

#include "scene/registered_keys.hpp"
#include "scene/schema.hpp"

namespace ryushi {

namespace {
std::string first_sentence(const std::string& doc) {
  const auto end = doc.find(". ");
  return end == std::string::npos ? doc : doc.substr(0, end + 1);
}
void key_lines(std::ostringstream& out, const std::string& prefix, const std::vector<KeySpec>& keys) {
  for (auto& k : keys) {
    out << "  " << prefix << k.key << "  " << type_name(k.type) << (k.unit.empty() ? "" : " [" + k.unit + "]")
        << (k.required                ? "  required"
            : k.default_value.empty() ? ""
                                      : "  default " + k.default_value)
        << "\n"
        << "      " << first_sentence(k.doc) << "\n";
  }
}
}  // namespace

std::string schema_text() {
  std::ostringstream out;
  out << "Scene keys (TOML; SI units). The whole text of each: ryushi keys --markdown, or docs/scenes.md.\n";
  for (auto& s : scene_schema()) {
    out << "\n"
        << (s.array_of_tables ? "[[" + s.name + "]]" : "[" + s.name + "]")
        << (s.required ? " (required)" : "") << "  " << first_sentence(s.doc) << "\n";
    key_lines(out, s.name + ".", s.keys);
    if (s.name != "method") continue;
    for (auto& name : method_spec_names())
      if (!find_method_spec(name)->keys.empty()) {
        out << "  (name = \"" << name << "\")\n";
        key_lines(out, "method.", find_method_spec(name)->keys);
      }
  }
  out << "\n[[systems]]  Registered systems and their keys.\n";
  for (auto& name : system_key_names()) {
    out << "  (name = \"" << name << "\")\n";
    key_lines(out, "systems.", find_system_keys(name)->keys);
  }
  return out.str();
}

}  // namespace ryushi
