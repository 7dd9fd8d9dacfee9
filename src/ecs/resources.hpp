#pragma once
// Resources: named, typed singletons shared by systems (neighbour list, dt, domain, matrices).
// Like components they are declared in a system's access set, so the scheduler orders systems
// that touch the same resource.
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <typeindex>

namespace ryushi {

template <class T>
struct Resource {
  using type = T;
  std::string_view name;
};

class Resources {
 public:
  template <class T>
  T& ensure(Resource<T> r) {
    auto it = slots_.find(std::string(r.name));
    if (it == slots_.end()) {
      Slot s{std::type_index(typeid(T)), std::make_shared<T>()};
      it = slots_.emplace(std::string(r.name), std::move(s)).first;
    }
    return cast<T>(it->second, r.name);
  }
  template <class T>
  T& get(Resource<T> r) {
    auto it = slots_.find(std::string(r.name));
    if (it == slots_.end())
      throw std::logic_error("resource '" + std::string(r.name) + "' was never created");
    return cast<T>(it->second, r.name);
  }
  template <class T>
  const T& get(Resource<T> r) const {
    return const_cast<Resources&>(*this).get(r);  // the same lookup; nothing is created
  }
  bool has(std::string_view name) const { return slots_.count(std::string(name)) != 0; }

 private:
  struct Slot {
    std::type_index type;
    std::shared_ptr<void> value;
  };
  template <class T>
  static T& cast(Slot& s, std::string_view name) {
    if (s.type != std::type_index(typeid(T)))
      throw std::logic_error("resource '" + std::string(name) + "' used with the wrong type");
    return *static_cast<T*>(s.value.get());
  }
  std::map<std::string, Slot> slots_;
};

// Resources every method shares.
namespace resources {
inline constexpr Resource<double> dt{"dt"};
// The step the time-step control chose, before the driver shortened dt to land on an output or
// the end time. A projection whose pressure scales with 1/dt^2 scales it with this one, so a
// shortened step does not change the pressure (only how much of it the step applies).
inline constexpr Resource<double> dt_chosen{"dt_chosen"};
// The largest step a system allows whatever the flow's speed (a capillary wave's), set once in
// its initialise; the driver shortens the time-step control's step to it. Absent: no limit.
inline constexpr Resource<double> dt_limit{"dt_limit"};
inline constexpr Resource<double> time{"time"};
inline constexpr Resource<long long> step{"step"};  // steps completed before this one
}  // namespace resources

}  // namespace ryushi
