#pragma once
// Access: what a system reads and writes (component columns and resources). The scheduler
// derives ordering edges from it and SystemContext refuses any access not declared here, so a
// wrong declaration fails loudly instead of racing.
#include <map>
#include <set>
#include <string>

#include "ecs/column.hpp"
#include "ecs/component.hpp"
#include "ecs/resources.hpp"

namespace ryushi {

struct Access {
  std::set<std::string> reads;
  std::set<std::string> writes;
  std::map<std::string, ColumnType> columns;  // component columns to allocate, by name
  // Names among reads and writes declared only to order the system against others (an edge
  // of the flow graph): the system never fetches them (io.hpp, order_only).
  std::set<std::string> ordering;

  template <class... Items>
  Access& read(const Items&... items) {
    (add(reads, items), ...);
    return *this;
  }
  template <class... Items>
  Access& write(const Items&... items) {
    (add(writes, items), ...);
    return *this;
  }
  bool may_read(const std::string& name) const { return reads.count(name) || writes.count(name); }
  bool may_write(const std::string& name) const { return writes.count(name) != 0; }

  // True when b must not run concurrently with a (read-after-write, write-after-read, write-
  // after-write on any shared name).
  static bool conflict(const Access& a, const Access& b) {
    for (auto& w : a.writes)
      if (b.reads.count(w) || b.writes.count(w)) return true;
    for (auto& w : b.writes)
      if (a.reads.count(w)) return true;
    return false;
  }

 private:
  template <class Kind>
  void add(std::set<std::string>& set, const Component<Kind>& c) {
    set.emplace(c.name);
    columns[std::string(c.name)] = column_type_of<Kind>();
  }
  template <class T>
  void add(std::set<std::string>& set, const Resource<T>& r) {
    set.emplace(r.name);
  }
};

}  // namespace ryushi
