/// \file epavi.hpp
/// \brief Energy-preserving adaptive variational integrator (EpAVI), Sharma et al. 2022 §2.2
/// and §3.2.1: the time-marching form (15)–(18) of the midpoint extended discrete
/// Lagrangian (25) for a mechanical Lagrangian, started as in the paper: a first step of
/// length h0 taken from an accurate solution fixes the discrete energy; after that the step
/// follows from the dynamics.
///
/// Chapter: \ref chapter-epavi.
#pragma once

#include "vibook/avi/avi.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"
#include "vibook/mechanics/extended.hpp"

namespace vibook {

/// EpAVI (Sharma et al. 2022, §2.2: the time-marching form (15)–(18) of the midpoint extended
/// discrete Lagrangian (25)) for a mechanical problem (potential templated on its scalar),
/// computed in T.
template <class Problem, class T = double>
class EpAVI {
 public:
  static constexpr int N = Problem::N;
  using Lagrangian = decltype(mechanical_lagrangian(std::declval<Problem>()));
  using DiscreteLagrangian = decltype(extended_midpoint_dl(std::declval<Lagrangian>()));
  using Integrator = ExtendedDelIntegrator<N, DiscreteLagrangian, T>;
  using State = ExtendedState<N, T>;
  using Options = typename Integrator::Options;

  /// (25) for an autonomous L depends on the times only through t1 − t0: EpAVI sets
  /// Options::time_translation_invariant unless `absolute_time` asks for the plain evaluation.
  explicit EpAVI(Problem P, Options options = {}, bool absolute_time = false)
      : vi_(extended_midpoint_dl(mechanical_lagrangian(P)), invariant(options, !absolute_time)) {}

  /// Start from (t0, q0) with the first step to (t0 + h0, q1), q1 from an accurate solution.
  State start(const T& t0, const Vec<T, N>& q0, const T& h0, const Vec<T, N>& q1) {
    return vi_.start(t0, q0, T(t0 + h0), q1);
  }
  ExtendedStepReport step(State& s) { return vi_.step(s); }
  const Integrator& integrator() const { return vi_; }
  Integrator& integrator() { return vi_; }

 private:
  static Options invariant(Options o, bool on) {
    o.time_translation_invariant = on;
    return o;
  }
  Integrator vi_;
};

}  // namespace vibook
