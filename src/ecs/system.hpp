#pragma once
// A system: a named piece of work over the world with a declared access set. Systems obtain
// their columns and resources through SystemContext using the same tokens they declare, and
// any access outside the declaration throws AccessViolation (per system run, not per particle,
// so the check stays on in every build type). The context also records what was fetched, so a
// declaration the system never uses is found too (tests/access_declaration_test.cpp).
#include <functional>
#include <memory>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "ecs/access.hpp"
#include "ecs/world.hpp"

namespace ryushi {

class AccessViolation : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

// Names fetched through a context; std::less<> finds a name without building a string.
using FetchedNames = std::set<std::string, std::less<>>;

template <int D>
class SystemContext {
 public:
  // fetched: where to record the names fetched (null: not recorded).
  SystemContext(World<D>& world, Resources& res, const Access& access, std::string_view system,
                FetchedNames* fetched = nullptr)
      : world_(world), res_(res), access_(access), system_(system), fetched_(fetched) {}

  std::size_t size() const { return world_.size(); }
  std::uint64_t structure_version() const { return world_.structure_version(); }

  template <class Kind>
  std::span<const element_t<Kind, D>> read(Component<Kind> c) const {
    if (!access_.may_read(std::string(c.name))) violation("reads", "component", c.name);
    record(c.name);
    return world_.column(c);
  }
  template <class Kind>
  std::span<element_t<Kind, D>> write(Component<Kind> c) const {
    if (!access_.may_write(std::string(c.name))) violation("writes", "component", c.name);
    record(c.name);
    return world_.column(c);
  }
  template <class T>
  const T& read(Resource<T> r) const {
    if (!access_.may_read(std::string(r.name))) violation("reads", "resource", r.name);
    record(r.name);
    return res_.get(r);
  }
  template <class T>
  T& write(Resource<T> r) const {
    if (!access_.may_write(std::string(r.name))) violation("writes", "resource", r.name);
    record(r.name);
    return res_.get(r);
  }
  std::string_view system_name() const { return system_; }

 private:
  // Once per fetch, which is once per system run: not on any particle's path.
  void record(std::string_view name) const {
    if (fetched_ && fetched_->find(name) == fetched_->end()) fetched_->emplace(name);
  }
  [[noreturn]] void violation(const char* verb, const char* what, std::string_view name) const {
    throw AccessViolation("system '" + std::string(system_) + "' " + verb + " " + what + " '" +
                          std::string(name) + "' without declaring it");
  }
  World<D>& world_;
  Resources& res_;
  const Access& access_;
  std::string_view system_;
  FetchedNames* fetched_;
};

template <int D>
class System {
 public:
  virtual ~System() = default;
  virtual std::string name() const = 0;
  virtual Access access() const = 0;
  // Called once before the first step, outside the flow graph: may allocate and fill columns
  // (initial conditions) and create resources.
  virtual void initialise(World<D>&, Resources&) {}
  virtual void run(SystemContext<D>& ctx) = 0;
  // A system added by a scene ([[systems]]) goes after the method's last system unless it names
  // the one it must follow (surface tension acts between the free-surface detection and the
  // pressure rows that read it); the method's step must then hold a system of that name.
  virtual std::string place_after() const { return {}; }
  // Checkpoints: what a system keeps between steps that no column holds (a Verlet list's
  // reference positions), as numbers, and its restore after the columns are back. Systems that
  // keep nothing leave both alone.
  virtual std::vector<double> checkpoint_state(const World<D>&, const Resources&) const { return {}; }
  virtual void restore_state(const World<D>&, Resources&, std::span<const double>) {}
};

template <int D>
using SystemPtr = std::shared_ptr<System<D>>;

// Structural changes a system asks for (particle splitting's children): recorded during the
// step, applied by the driver after it, before the health check and the output.
template <int D>
inline constexpr Resource<CommandBuffer<D>> structural_changes_resource{"structural_changes"};

}  // namespace ryushi
