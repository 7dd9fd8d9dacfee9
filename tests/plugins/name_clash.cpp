// A plugin that registers a system under a new name and a method under a name ryushi already
// has: refused with exit 2, and neither name stays registered.
#include "methods/plugin.hpp"

RYUSHI_PLUGIN();

namespace ryushi::test_plugin {

template <int D>
class Nothing final : public System<D> {
 public:
  Nothing(const toml::table&, const MethodContext<D>&) {}
  std::string name() const override { return "clash_nothing"; }
  Access access() const override { return Access{}; }
  void run(SystemContext<D>&) override {}
};

template <int D>
MethodSetup<D> build_nothing(const Scene&, World<D>&, const PipelineOptions&) {
  return {};
}

MethodSpec second_wcsph() {
  MethodSpec spec;
  spec.doc = "a second wcsph";
  return spec;
}

RYUSHI_REGISTER_SYSTEM(Nothing, "clash_nothing", "A system that does nothing.", {});
RYUSHI_REGISTER_METHOD("wcsph", second_wcsph(), build_nothing);

}  // namespace ryushi::test_plugin
