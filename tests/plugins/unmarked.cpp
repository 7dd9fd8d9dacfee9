// A shared library without RYUSHI_PLUGIN(): not a ryushi plugin.
extern "C" int not_a_plugin() {
  return 1;
}
