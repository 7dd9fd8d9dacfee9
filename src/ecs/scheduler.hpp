#pragma once
// Scheduler: turns a method's ordered system list into a oneTBB flow graph. For systems i < j
// an edge i -> j is added when their access sets conflict (read-after-write, write-after-read,
// write-after-write), so the graph keeps the list's meaning while independent systems overlap.
// The graph is built once and triggered once per step.
#include <tbb/flow_graph.h>

#include <atomic>
#include <exception>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "ecs/profiler.hpp"
#include "ecs/system.hpp"

namespace ryushi {

template <int D>
class Scheduler {
 public:
  Scheduler(std::vector<SystemPtr<D>> pipeline, World<D>& world, Resources& res, Profiler& profiler)
      : pipeline_(std::move(pipeline)), world_(world), res_(res), profiler_(profiler), start_(graph_) {
    for (auto& s : pipeline_) {
      accesses_.push_back(s->access());
      names_.push_back(s->name());
      slots_.push_back(profiler_.slot(names_.back()));
    }
    fetched_.resize(pipeline_.size());
    allocate_columns();
    build_graph();
  }

  // Allocates every column any system declares, before anything runs concurrently.
  void allocate_columns() {
    for (auto& a : accesses_)
      for (auto& [name, type] : a.columns) ensure_column(name, type);
  }

  void initialise() {
    for (auto& s : pipeline_) s->initialise(world_, res_);
  }

  // Runs one step: every system once, in an order consistent with the edges.
  void step() {
    start_.try_put(tbb::flow::continue_msg());
    graph_.wait_for_all();
    if (failed_) {
      auto f = failure_;
      failure_ = nullptr;
      failed_ = false;
      graph_.reset();
      std::rethrow_exception(f);
    }
  }

  // Edges as (from, to) pipeline indices, for tests and docs.
  const std::vector<std::pair<std::size_t, std::size_t>>& edges() const { return edges_; }
  const std::vector<SystemPtr<D>>& pipeline() const { return pipeline_; }
  const std::vector<Access>& accesses() const { return accesses_; }
  // The names each system fetched, over every step run so far (against accesses(): a declared
  // name no run fetched is a stale declaration).
  const std::vector<FetchedNames>& fetched() const { return fetched_; }

  // The last system in the pipeline that writes a name (for naming the culprit of a failure).
  std::string last_writer(const std::string& name) const {
    for (std::size_t i = pipeline_.size(); i-- > 0;)
      if (accesses_[i].may_write(name)) return names_[i];
    return "initial conditions";
  }

 private:
  void ensure_column(const std::string& name, ColumnType type);

  void build_graph() {
    using Node = tbb::flow::continue_node<tbb::flow::continue_msg>;
    for (std::size_t i = 0; i < pipeline_.size(); ++i) {
      nodes_.push_back(std::make_unique<Node>(graph_, [this, i](const tbb::flow::continue_msg&) {
        run_one(i);
      }));
      bool has_predecessor = false;
      // Nearest predecessors first, so edges implied through them can be recognised.
      for (std::size_t j = i; j-- > 0;) {
        if (!Access::conflict(accesses_[j], accesses_[i])) continue;
        // Skip edges implied by a path through another predecessor: fewer edges, same order.
        if (reachable_via_others(j, i)) continue;
        tbb::flow::make_edge(*nodes_[j], *nodes_[i]);
        edges_.emplace_back(j, i);
        has_predecessor = true;
      }
      if (!has_predecessor) tbb::flow::make_edge(start_, *nodes_[i]);
    }
  }

  // True if j reaches i through some k (j < k < i) that i already depends on.
  bool reachable_via_others(std::size_t j, std::size_t i) const {
    for (auto& [from, to] : edges_)
      if (to == i && from > j && reaches(j, from)) return true;
    return false;
  }
  bool reaches(std::size_t a, std::size_t b) const {
    if (a == b) return true;
    for (auto& [from, to] : edges_)
      if (from == a && to <= b && reaches(to, b)) return true;
    return false;
  }

  void run_one(std::size_t i) {
    if (failed_) return;  // a failed step skips the rest
    auto begin = Profiler::Clock::now();
    try {
      // Each system's set is written only by its own node, which never runs twice at once.
      SystemContext<D> ctx(world_, res_, accesses_[i], names_[i], &fetched_[i]);
      pipeline_[i]->run(ctx);
    } catch (const AccessViolation&) {
      fail(std::current_exception());
    } catch (const std::exception& e) {
      // Name the system, so a numerical failure report says where it happened.
      fail(std::make_exception_ptr(std::runtime_error("system '" + names_[i] + "': " + e.what())));
    } catch (...) {
      fail(std::current_exception());
    }
    profiler_.record(slots_[i], begin, Profiler::Clock::now());
  }

  void fail(std::exception_ptr e) {
    std::lock_guard lock(failure_mutex_);
    if (!failure_) failure_ = e;
    failed_ = true;
  }

  std::vector<SystemPtr<D>> pipeline_;
  World<D>& world_;
  Resources& res_;
  Profiler& profiler_;
  std::vector<Access> accesses_;
  std::vector<std::string> names_;
  std::vector<std::size_t> slots_;
  std::vector<FetchedNames> fetched_;
  tbb::flow::graph graph_;
  tbb::flow::broadcast_node<tbb::flow::continue_msg> start_;
  std::vector<std::unique_ptr<tbb::flow::continue_node<tbb::flow::continue_msg>>> nodes_;
  std::vector<std::pair<std::size_t, std::size_t>> edges_;
  std::exception_ptr failure_;
  std::atomic<bool> failed_{false};
  std::mutex failure_mutex_;
};

template <int D>
void Scheduler<D>::ensure_column(const std::string& name, ColumnType type) {
  if (world_.has(name)) {
    if (world_.column_type(name) != type)
      throw std::logic_error("component '" + name + "' declared with two different types");
    return;
  }
  switch (type) {
    case ColumnType::Scalar: world_.ensure(Component<Scalar>{name}); break;
    case ColumnType::Vector: world_.ensure(Component<Vector>{name}); break;
    case ColumnType::Tensor: world_.ensure(Component<Tensor>{name}); break;
    case ColumnType::Flags: world_.ensure(Component<Flags>{name}); break;
  }
}

}  // namespace ryushi
