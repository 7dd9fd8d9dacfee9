#include <doctest/doctest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <thread>

#include "ecs/scheduler.hpp"

using namespace ryushi;
using Clock = std::chrono::steady_clock;

namespace {

constexpr Component<Scalar> ca{"a"}, cb{"b"}, cc{"c"};

struct ToySystem : System<2> {
  std::string n;
  Access acc;
  std::function<void(SystemContext<2>&)> body;
  Clock::time_point begin, end;
  ToySystem(std::string name, Access a, std::function<void(SystemContext<2>&)> f = {})
      : n(std::move(name)), acc(std::move(a)), body(std::move(f)) {}
  std::string name() const override { return n; }
  Access access() const override { return acc; }
  void run(SystemContext<2>& ctx) override {
    begin = Clock::now();
    if (body) body(ctx);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    end = Clock::now();
  }
};

// Waits (bounded) until `flag` is set; true if it was.
bool wait_for(const std::atomic<bool>& flag) {
  auto until = Clock::now() + std::chrono::seconds(5);
  while (!flag && Clock::now() < until) std::this_thread::yield();
  return flag;
}

}  // namespace

TEST_CASE("scheduler: edges follow read-after-write, write-after-read, write-after-write") {
  World<2> w;
  w.append(4, kFluid);
  Resources res;
  Profiler prof;
  auto w_a = std::make_shared<ToySystem>("write_a", Access{}.write(ca));
  auto r_a = std::make_shared<ToySystem>("read_a_write_b", Access{}.read(ca).write(cb));
  auto w_a2 = std::make_shared<ToySystem>("write_a_again", Access{}.write(ca));  // WAR on a
  auto w_c = std::make_shared<ToySystem>("write_c", Access{}.write(cc));       // independent
  auto w_b = std::make_shared<ToySystem>("write_b", Access{}.write(cb));       // WAW on b
  Scheduler<2> s({w_a, r_a, w_a2, w_c, w_b}, w, res, prof);
  auto edges = s.edges();
  std::sort(edges.begin(), edges.end());
  std::vector<std::pair<std::size_t, std::size_t>> expected{{0, 1}, {1, 2}, {1, 4}};
  CHECK(edges == expected);  // (0,2) is implied through 1 and left out
  CHECK(w.has("a"));             // declared columns are allocated up front
  CHECK(w.has("c"));
}

TEST_CASE("scheduler: dependent systems never overlap, independent ones do") {
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 2);
  World<2> w;
  w.append(4, kFluid);
  Resources res;
  Profiler prof;
  std::atomic<bool> a_started{false}, b_started{false};
  bool a_saw_b = false, b_saw_a = false;
  // Two independent systems that each wait for the other to start: only possible if the graph
  // runs them at the same time.
  auto a = std::make_shared<ToySystem>("independent_a", Access{}.write(ca), [&](auto&) {
    a_started = true;
    a_saw_b = wait_for(b_started);
  });
  auto b = std::make_shared<ToySystem>("independent_b", Access{}.write(cb), [&](auto&) {
    b_started = true;
    b_saw_a = wait_for(a_started);
  });
  auto after = std::make_shared<ToySystem>("reads_a_and_b", Access{}.read(ca, cb).write(cc));
  auto war = std::make_shared<ToySystem>("overwrites_a", Access{}.write(ca));
  Scheduler<2> s({a, b, after, war}, w, res, prof);
  // Overlap needs two CPUs; the edges hold on any machine.
  const bool two_cpus = std::thread::hardware_concurrency() >= 2;
  if (!two_cpus) MESSAGE("one CPU: the overlap of the independent systems is not checked, the edges are");
  for (int step = 0; step < 5; ++step) {
    a_started = b_started = false;
    s.step();
    if (two_cpus) {
      CHECK(a_saw_b);
      CHECK(b_saw_a);
    }
    CHECK(after->begin >= a->end);
    CHECK(after->begin >= b->end);
    CHECK(war->begin >= after->end);
  }
  auto& e = prof.entries();
  REQUIRE(e.size() == 4);
  CHECK(e[0].calls == 5);
  CHECK(e[0].total_s > 0);
}

TEST_CASE("scheduler: an undeclared access is caught, not raced") {
  World<2> w;
  w.append(4, kFluid);
  Resources res;
  Profiler prof;
  auto sneaky_write = std::make_shared<ToySystem>("sneaky_write", Access{}.read(ca), [](SystemContext<2>& ctx) {
    ctx.write(ca)[0] = 1.0;  // declared read only
  });
  Scheduler<2> s1({sneaky_write}, w, res, prof);
  CHECK_THROWS_WITH_AS(s1.step(), "system 'sneaky_write' writes component 'a' without declaring it", AccessViolation);

  auto sneaky_read = std::make_shared<ToySystem>("sneaky_read", Access{}.write(cb), [](SystemContext<2>& ctx) {
    (void)ctx.read(ca);
  });
  Scheduler<2> s2({sneaky_read}, w, res, prof);
  CHECK_THROWS_AS(s2.step(), AccessViolation);
  CHECK_THROWS_AS(s2.step(), AccessViolation);  // the graph is reusable after a failure
}

TEST_CASE("profiler: json and Chrome trace name every system run") {
  World<2> w;
  w.append(1, kFluid);
  Resources res;
  Profiler prof(true);
  auto a = std::make_shared<ToySystem>("alpha", Access{}.write(ca));
  auto b = std::make_shared<ToySystem>("beta", Access{}.read(ca).write(cb));
  Scheduler<2> s({a, b}, w, res, prof);
  s.step();
  s.step();
  auto trace = prof.trace_json();
  CHECK(trace.find("\"traceEvents\"") != std::string::npos);
  std::size_t spans = 0;
  for (std::size_t pos = 0; (pos = trace.find("\"ph\": \"X\"", pos)) != std::string::npos; ++pos) ++spans;
  CHECK(spans == 4);
  auto json = prof.json();
  CHECK(json.find("\"name\": \"beta\"") != std::string::npos);
  CHECK(json.find("\"calls\": 2") != std::string::npos);
}
