#pragma once
// System registry: user systems register themselves by name next to their implementation
// (no central list to edit). A scene adds them with [[systems]] name = "...", and the
// scheduler places them in the flow graph by their declared access.
//
//   RYUSHI_REGISTER_SYSTEM(MySystem, "my_system", "What it does.", { KeySpec... });
// optionally followed by what the method must provide and a check across the scene's sections
// (SystemKeys::validate).
// where MySystem<D> has a constructor MySystem(const toml::table& params, const MethodContext<D>&):
// the method-neutral context (kernel, spacing, domain, gravity, material, method name), so the
// same system runs under every method.
#include <toml++/toml.h>

#include <functional>
#include <string>
#include <vector>

#include "ecs/system.hpp"
#include "methods/method_context.hpp"
#include "scene/registered_keys.hpp"
#include "scene/schema.hpp"

namespace ryushi {

struct SystemRegistryEntry {
  SystemKeys keys;  // doc, [[systems]] keys, needs, validate: what the scene loader checks
  std::function<SystemPtr<2>(const toml::table&, const MethodContext<2>&)> make2;
  std::function<SystemPtr<3>(const toml::table&, const MethodContext<3>&)> make3;
};

// Throws std::logic_error for a name already registered (by ryushi or a plugin).
bool register_system(const std::string& name, SystemRegistryEntry entry);
void unregister_system(const std::string& name);
std::vector<std::string> system_registry_names();
bool system_registered(const std::string& name);
const SystemRegistryEntry& system_registry_entry(const std::string& name);

template <int D>
SystemPtr<D> make_registered_system(const std::string& name, const toml::table& params,
                                    const MethodContext<D>& context) {
  auto& e = system_registry_entry(name);
  if constexpr (D == 2)
    return e.make2(params, context);
  else
    return e.make3(params, context);
}

template <template <int> class T>
SystemRegistryEntry registry_entry(std::string doc, std::vector<KeySpec> params,
                                   std::vector<std::string> needs = {},
                                   decltype(SystemKeys::validate) validate = {}) {
  return {SystemKeys{std::move(doc), std::move(params), std::move(needs), std::move(validate)},
          [](const toml::table& p, const MethodContext<2>& w) { return std::make_shared<T<2>>(p, w); },
          [](const toml::table& p, const MethodContext<3>& w) { return std::make_shared<T<3>>(p, w); }};
}

#define RYUSHI_CONCAT_INNER(a, b) a##b
#define RYUSHI_CONCAT(a, b) RYUSHI_CONCAT_INNER(a, b)
#define RYUSHI_REGISTER_SYSTEM(TEMPLATE, NAME, DOC, ...)                           \
  [[maybe_unused]] static const bool RYUSHI_CONCAT(ryushi_registered_, __LINE__) = \
      ::ryushi::register_system(NAME, ::ryushi::registry_entry<TEMPLATE>(DOC, __VA_ARGS__))

}  // namespace ryushi
