#pragma once
// What a plugin library includes (docs/extending.md, examples/out_of_tree/): the registration
// macros of methods (RYUSHI_REGISTER_METHOD) and systems (RYUSHI_REGISTER_SYSTEM), and
//
//   RYUSHI_PLUGIN();
//
// written once in one of its files: it marks the library as a ryushi plugin built against this
// version. ryushi reads the mark from the file before it loads the library, so a library built
// against another version is refused before any of its code runs.
#include "methods/method.hpp"
#include "methods/system_registry.hpp"
#include "ryushi_version.hpp"

#define RYUSHI_PLUGIN_MARK "ryushi-plugin-version="

#define RYUSHI_PLUGIN()                                                                  \
  [[gnu::used, gnu::section(".ryushi_plugin")]] static const char ryushi_plugin_mark[] = \
      RYUSHI_PLUGIN_MARK RYUSHI_VERSION ";"
