// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Starts of optimize_seams() run side by side: the visitor each one calls,
// what one hands to another, and running them (in parallel where TBB is
// linked).

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_PARALLEL_STARTS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_PARALLEL_STARTS_H

#include <CGAL/Surface_mesh_seam_optimization/Seam_optimization_visitor.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#include <tbb/task_group.h>
#endif

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <memory>
#include <mutex>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// The other starts' effort is bounded by the first's: each does at most
// `factor` times the first start's Newton iterations, so that two starts
// take at most about that many times one start. Deterministic whatever the
// schedule: while the first start runs, another waits whenever it would get
// ahead of `factor` times the first's count so far, and once the first is
// done the bound is final.
class Iteration_budget
{
public:
  explicit Iteration_budget(double factor) : m_factor(factor) {}

  void first_iterated()
  {
    { std::lock_guard<std::mutex> lock(m_mutex); ++m_first; }
    m_changed.notify_all();
  }
  void first_done()
  {
    { std::lock_guard<std::mutex> lock(m_mutex); m_done = true; }
    m_changed.notify_all();
  }
  // whether another start may do its n-th iteration, within `share` of the
  // budget (1: `factor` times the first's iterations)
  bool second_may_go(std::size_t n, double share = 1.)
  {
    std::unique_lock<std::mutex> lock(m_mutex);
    m_changed.wait(lock, [&] { return m_done || within(n, share); });
    return within(n, share);
  }

private:
  bool within(std::size_t n, double share) const { return double(n) <= share * m_factor * double(m_first); }

  double m_factor;
  std::mutex m_mutex;
  std::condition_variable m_changed;
  std::size_t m_first = 0;
  bool m_done = false;
};

// What one start hands to another once (a forked run, or nothing): take()
// waits until it is settled, so that the taker's result does not depend on
// the schedule.
template <typename T>
class Handoff
{
public:
  void give(std::unique_ptr<T> t)
  {
    { std::lock_guard<std::mutex> lock(m_mutex); if(!m_settled) m_item = std::move(t); m_settled = true; }
    m_changed.notify_all();
  }
  void settle() { give(nullptr); }
  std::unique_ptr<T> take()
  {
    std::unique_lock<std::mutex> lock(m_mutex);
    m_changed.wait(lock, [&] { return m_settled; });
    return std::move(m_item);
  }

private:
  std::mutex m_mutex;
  std::condition_variable m_changed;
  std::unique_ptr<T> m_item;
  bool m_settled = false;
};

// The visitor of one start: the user's visitor for the start run on the
// calling thread (so that it is never called from another thread), none for
// the others. A stop asked by the user's visitor stops every start. With a
// budget, the first start reports its iterations to it and another stops
// (alone) when its `share` of it is spent.
template <typename Visitor>
class Start_visitor
{
public:
  Start_visitor(Visitor* user, std::atomic<bool>& stop, Iteration_budget* budget = nullptr, bool first = true,
                double share = 1.)
    : m_user(user), m_stop(stop), m_budget(budget), m_first(first), m_share(share) {}

  bool on_iteration(const Seam_optimization_progress& p)
  {
    if(m_budget)
    {
      if(m_first) m_budget->first_iterated();
      else if(!m_budget->second_may_go(++m_iterations, m_share)) return false;
    }
    return go(!m_user || m_user->on_iteration(p));
  }
  // (a start that takes over another's run counts its iterations too)
  void add_iterations(std::size_t n) { m_iterations += n; }
  // (a start run again from its beginning)
  void restart() { m_iterations = 0; }

  bool on_topology_operation(const Seam_optimization_progress& p)
  {
    return go(!m_user || m_user->on_topology_operation(p));
  }
  bool on_lambda_update(const Seam_optimization_progress& p) { return go(!m_user || m_user->on_lambda_update(p)); }
  bool reads_progress() const { return m_user && visitor_reads_progress(*m_user); }

private:
  bool go(bool user_goes)
  {
    if(!user_goes) m_stop.store(true);
    return user_goes && !m_stop.load();
  }

  Visitor* m_user;
  std::atomic<bool>& m_stop;
  Iteration_budget* m_budget;
  bool m_first;
  double m_share;
  std::size_t m_iterations = 0;
};

// Runs first() on the calling thread and second() beside it. Each works on
// its own data, so the results do not depend on the schedule; without TBB
// they run one after the other. `stop` is raised if first() throws, so that
// second() ends soon.
template <typename First, typename Second>
void run_side_by_side(const First& first, const Second& second, std::atomic<bool>& stop)
{
#ifdef CGAL_LINKED_WITH_TBB
  tbb::task_group group;
  // isolated: a thread waiting inside one start (its parallel candidate
  // scoring) takes no work of the other start, which would hold it up
  group.run([&] { tbb::this_task_arena::isolate(second); });
  try
  {
    tbb::this_task_arena::isolate(first);
  }
  catch(...)
  {
    stop.store(true);
    group.wait();
    throw;
  }
  group.wait();
#else
  (void)stop;
  first();
  second();
#endif
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
