#pragma once
// Io: a system's reads and writes, listed once. access() declares them to the scheduler and
// fetch() takes them from the context in the order listed, so a system cannot declare a column
// or resource it never fetches by forgetting one of two lists (issue 48; the declaration and the
// fetches were separate lists, and drifted). tests/access_declaration_test.cpp checks, for every
// system of every method, that what a run fetched is what it declared.
//
//   static constexpr auto io = Io{reads(components::kind, neighbours_resource, resources::dt),
//                                 writes(components::velocity)};
//   Access access() const override { return io.access(); }
//   void run(SystemContext<D>& ctx) override { auto [kind, nl, dt, v] = io.fetch(ctx); ... }
//
// A read column comes back as std::span<const T>, a read resource as const R&, a written column
// as std::span<T> and a written resource as R&.
//
// Access that depends on the instance's options:
//   optional(flag, reads(...), writes(...))  declared and fetched only where flag is true; when
//     false its columns come back as empty spans and its resources as null pointers.
//   A list that depends on options fixed at construction (a column chosen by the scene) is built
//     by a member function, auto io() const { return Io{...}; }, called by access() and run().
// A name declared only to order the system against others (an edge of the flow graph, nothing
// fetched): order_only(reads(...)) or order_only(writes(...)); the check expects no fetch of it.
#include <span>
#include <tuple>

#include "ecs/access.hpp"
#include "ecs/system.hpp"

namespace ryushi {

namespace io_detail {

template <bool Write, int D, class Kind>
auto fetch_one(SystemContext<D>& ctx, const Component<Kind>& c) {
  if constexpr (Write)
    return ctx.write(c);
  else
    return ctx.read(c);
}
template <bool Write, int D, class T>
auto& fetch_one(SystemContext<D>& ctx, const Resource<T>& r) {
  if constexpr (Write)
    return ctx.write(r);
  else
    return ctx.read(r);
}

// What an optional entry gives when its flag is false: an empty span, or a null pointer.
template <bool Write, int D, class Kind>
auto fetch_if(SystemContext<D>& ctx, const Component<Kind>& c, bool on) {
  return on ? fetch_one<Write>(ctx, c) : decltype(fetch_one<Write>(ctx, c)){};
}
template <bool Write, int D, class T>
auto* fetch_if(SystemContext<D>& ctx, const Resource<T>& r, bool on) {
  return on ? &fetch_one<Write>(ctx, r) : nullptr;
}

}  // namespace io_detail

// reads(...) and writes(...): one direction of access over component and resource tokens.
template <bool Write, class... Tokens>
struct IoList {
  std::tuple<Tokens...> tokens;

  void declare(Access& a) const {
    std::apply(
        [&](const auto&... t) {
          if constexpr (Write)
            a.write(t...);
          else
            a.read(t...);
        },
        tokens);
  }
  template <int D>
  auto fetch(SystemContext<D>& ctx) const {
    // Braced initialisation: the fetches happen in the order listed.
    return std::apply(
        [&](const auto&... t) {
          return std::tuple<decltype(io_detail::fetch_one<Write>(ctx, t))...>{
              io_detail::fetch_one<Write>(ctx, t)...};
        },
        tokens);
  }
  template <int D>
  auto fetch_if(SystemContext<D>& ctx, bool on) const {
    return std::apply(
        [&](const auto&... t) {
          return std::tuple<decltype(io_detail::fetch_if<Write>(ctx, t, on))...>{
              io_detail::fetch_if<Write>(ctx, t, on)...};
        },
        tokens);
  }
};

template <class... Tokens>
constexpr IoList<false, Tokens...> reads(const Tokens&... t) {
  return {{t...}};
}
template <class... Tokens>
constexpr IoList<true, Tokens...> writes(const Tokens&... t) {
  return {{t...}};
}

// Lists declared and fetched only when `on` (an option of the instance).
template <class... Lists>
struct IoOptional {
  bool on;
  std::tuple<Lists...> lists;

  void declare(Access& a) const {
    if (on) std::apply([&](const auto&... l) { (l.declare(a), ...); }, lists);
  }
  template <int D>
  auto fetch(SystemContext<D>& ctx) const {
    return std::apply([&](const auto&... l) { return std::tuple_cat(l.fetch_if(ctx, on)...); }, lists);
  }
};

template <class... Lists>
constexpr IoOptional<Lists...> optional(bool on, const Lists&... lists) {
  return {on, {lists...}};
}

// A list declared for ordering only: the scheduler sees it, fetch returns nothing for it.
template <class List>
struct IoOrderOnly {
  List list;

  void declare(Access& a) const {
    Access own;
    list.declare(own);
    a.ordering.insert(own.reads.begin(), own.reads.end());
    a.ordering.insert(own.writes.begin(), own.writes.end());
    list.declare(a);
  }
  template <int D>
  std::tuple<> fetch(SystemContext<D>&) const {
    return {};
  }
};

template <class List>
constexpr IoOrderOnly<List> order_only(const List& list) {
  return {list};
}

template <class... Entries>
struct Io {
  std::tuple<Entries...> entries;

  constexpr Io(const Entries&... e) : entries(e...) {}

  // Adds this list to a (for a system that joins another object's list, an elastic model's).
  void declare(Access& a) const {
    std::apply([&](const auto&... e) { (e.declare(a), ...); }, entries);
  }
  Access access() const {
    Access a;
    declare(a);
    return a;
  }
  // Everything listed, in the order listed, flattened into one tuple for a structured binding.
  template <int D>
  auto fetch(SystemContext<D>& ctx) const {
    return std::apply([&](const auto&... e) { return std::tuple_cat(e.fetch(ctx)...); }, entries);
  }
};

}  // namespace ryushi
