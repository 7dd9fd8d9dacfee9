// Marks the library as a ryushi plugin built against the headers it was compiled with
// (methods/plugin.hpp): once per library.
#include "methods/plugin.hpp"

RYUSHI_PLUGIN();
