// Doctests of the compiled typed discrete Lagrangian (tape.hpp): the tape's value is the tree
// evaluator's to the bit, its derivatives are AutoDiff's to round-off, the integrator stepped
// through it follows the AutoDiff integrator's trajectory to round-off, and it evaluates in
// wider types. A tape of a different Lagrangian is told apart by the same comparisons.
#include "vibook/verify/tape.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>

#include "vibook/core/precision.hpp"
#include "vibook/core/tolerance.hpp"
#include "vibook/mechanics/del_solver.hpp"
#include "vibook/modified/engine.hpp"

using namespace vibook;
using vibook::verify::CompiledDiscreteLagrangian;
using vibook::verify::TypedDiscreteLagrangian;

namespace {

// The native code of these tests is cached in a directory of their own, removed at the end.
struct TestCache {
  std::string dir;
  TestCache() {
    char name[] = "/tmp/vibook-tape-test-XXXXXX";
    if (const char* d = mkdtemp(name)) {
      dir = d;
      setenv("VIBOOK_CACHE_DIR", d, 1);
    }
  }
  ~TestCache() {
    std::error_code ec;
    if (!dir.empty()) std::filesystem::remove_all(dir, ec);
  }
} test_cache;

bool native_expected() {
  const char* e = std::getenv("VIBOOK_NATIVE");
  return !(e && std::string(e) == "0");
}

struct Case {
  const char* ld;
  const char* potential;
};

// Every operation of the language: vectors, dot products, half-integer powers, the five
// functions, V at a vector, grad(V), products of q0 and q1.
const Case kCases[] = {
    {"h*((q1-q0)^2/(2*h^2) - (V(q0)+4*V((q0+q1)/2)+V(q1))/6)", "x^2/2+y^2/2+x^2*y-y^3/3"},
    {"h*((q1-q0)^2/(2*h^2) - V((q0+q1)/2))", "-1/sqrt(x^2+y^2)"},
    {"(q1-q0)^2/(2*h) - h*(V(q0)+V(q1))/2 + h^3/24*grad(V)((q0+q1)/2)^2", "-(x^2+y^2)^(-1/2)"},
    {"h*((q1-q0)^2/(2*h^2) - V(q0)) + 1/100*sin(q0[1]*q1[2])*exp(q1[1]-q0[2])",
     "log(2+x^2) - cos(y)"},
    {"(q1-q0)^2/(2*h) - h*q0*q1/2 - h*(q0^4+q1^4)/8", "x^4/2"},
    {"h*((q1-q0)^2/(2*h^2)*(1+q0[3]^2)^(3/2) - V(q1))", "x^2*y + z^3/3 + sqrt(1+x^2+y^2+z^2)"},
};

template <int N>
void compare_at(const TypedDiscreteLagrangian& dl, const CompiledDiscreteLagrangian<N>& c,
                const Vec<double, N>& a, const Vec<double, N>& b, double h) {
  const auto Ld = dl.bind<N>();
  const auto ad = ad::two_point<N>(Ld, a, b, h);
  const auto tp = c.template evaluate<double>(a, b, h);
  // The value: the same operations in the same order as the tree evaluator.
  CHECK(tp.value == Ld(a, b, h));
  // The derivatives: other operations than AutoDiff's, so round-off apart, relative to the
  // size of the derivatives (a sum of terms of that size).
  const double scale = 1 + ad.D1.template lpNorm<Eigen::Infinity>() +
                       ad.D2.template lpNorm<Eigen::Infinity>() +
                       ad.D12.template lpNorm<Eigen::Infinity>();
  CHECK((tp.D1 - ad.D1).template lpNorm<Eigen::Infinity>() <= 64 * kEps * scale);
  CHECK((tp.D2 - ad.D2).template lpNorm<Eigen::Infinity>() <= 64 * kEps * scale);
  CHECK((tp.D12 - ad.D12).template lpNorm<Eigen::Infinity>() <= 64 * kEps * scale);
  // The Newton parts and the momentum, as DelIntegrator calls them.
  Vec<double, N> D1;
  Mat<double, N> D12;
  c.newton_parts(a, b, h, D1, D12);
  CHECK(D1 == tp.D1);
  CHECK(D12 == tp.D12);
  CHECK(c.d2(a, b, h) == tp.D2);
  Vec<double, N> D1_alone;
  Mat<double, N> untouched = Mat<double, N>::Constant(7.0);
  c.newton_parts(a, b, h, D1_alone, untouched, false);  // D1 alone, for the final residual
  CHECK(D1_alone == tp.D1);
  CHECK(untouched == Mat<double, N>::Constant(7.0));
}

template <int N>
void compare_case(const TypedDiscreteLagrangian& dl) {
  // Native code where a C compiler is present (newton_parts and d2 then run it, and compare_at
  // holds them to the interpreter's evaluate() bit for bit), else the interpreter.
  const CompiledDiscreteLagrangian<N> c(dl);
  INFO("native code: ", c.native_reason());
  if (native_expected()) CHECK(c.native());
  CHECK(c.stats().newton_instructions > 0);
  for (int k = 0; k < 5; ++k) {
    Vec<double, N> a, b;
    for (int i = 0; i < N; ++i) {
      a(i) = 0.3 + 0.11 * i - 0.05 * k;
      b(i) = a(i) + 0.02 * (i + 1) - 0.01 * k;
    }
    compare_at<N>(dl, c, a, b, 0.05 + 0.01 * k);
  }
}

}  // namespace

TEST_CASE("tape: value to the bit, derivatives to round-off, on every operation") {
  std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
  for (const Case& cs : kCases) {
    INFO("--ld ", std::string(cs.ld), " --potential ", std::string(cs.potential));
    const TypedDiscreteLagrangian dl(cs.ld, cs.potential);
    switch (dl.dim()) {
      case 1:
        compare_case<1>(dl);
        break;
      case 2:
        compare_case<2>(dl);
        break;
      case 3:
        compare_case<3>(dl);
        break;
      default:
        FAIL("unexpected dimension ", dl.dim());
    }
  }
}

TEST_CASE("tape: the integrator through the tape follows the AutoDiff integrator") {
  std::unique_lock<std::recursive_mutex> lock(modified::ginac_mutex());
  // Kepler under the midpoint rule, e = 0.5 from perihelion: a nonlinear problem with close
  // approaches, 2000 steps (about 3 orbits).
  const TypedDiscreteLagrangian dl(kCases[1].ld, kCases[1].potential);
  const CompiledDiscreteLagrangian<2> compiled(dl);
  lock.unlock();
  const auto Ld = dl.bind<2>();
  DelIntegrator<2, decltype(Ld)> reference(Ld);
  DelIntegrator<2, CompiledDiscreteLagrangian<2>> fast(compiled);
  Vec<double, 2> qr(0.5, 0.0), pr(0.0, std::sqrt(3.0)), qf = qr, pf = pr;
  double worst = 0;
  for (int k = 0; k < 2000; ++k) {
    const SolveReport a = reference.step(qr, pr, 0.01);
    const SolveReport b = fast.step(qf, pf, 0.01);
    CHECK(b.iterations <= a.iterations + 1);
    worst =
        std::max(worst, (qr - qf).lpNorm<Eigen::Infinity>() + (pr - pf).lpNorm<Eigen::Infinity>());
  }
  // Round-off apart: differences of a few units of the last place per step, grown by the
  // twist of the Kepler flow over three orbits; a different method would differ by O(h²)
  // = 1e-4 (checked below).
  CHECK(worst <= 1e-11);
  CHECK(worst > 0);  // the two do compute differently (else this compares nothing)

  SUBCASE("a different discrete Lagrangian is told apart") {
    std::unique_lock<std::recursive_mutex> relock(modified::ginac_mutex());
    const TypedDiscreteLagrangian wrong("h*((q1-q0)^2/(2*h^2) - (V(q0)+V(q1))/2)",
                                        kCases[1].potential);
    const CompiledDiscreteLagrangian<2> cw(wrong);
    relock.unlock();
    DelIntegrator<2, CompiledDiscreteLagrangian<2>> other(cw);
    Vec<double, 2> q(0.5, 0.0), p(0.0, std::sqrt(3.0)), q2 = q, p2 = p;
    DelIntegrator<2, decltype(Ld)> ref2(Ld);
    double gap = 0;
    for (int k = 0; k < 2000; ++k) {
      ref2.step(q, p, 0.01);
      other.step(q2, p2, 0.01);
      gap = std::max(gap, (q - q2).lpNorm<Eigen::Infinity>());
    }
    CHECK(gap > 1e-6);
  }
}

TEST_CASE("tape: the trapezoidal rule, affine in q_(k+1): one factorisation, values carried") {
  // Kepler under the trapezoidal rule (Störmer–Verlet), e = 0.5 from perihelion, 2000 steps.
  // D2 D1 L_d = −I/h does not depend on q_(k+1): DelIntegrator solves the step by
  // affine_newton_solve. The prefix of step k+1 needs h/2 ∇V(q_(k+1)), which the momentum of
  // step k has computed: it is carried over (CompiledTapes), to the bit.
  std::unique_lock<std::recursive_mutex> lock(modified::ginac_mutex());
  const char* potential = "-1/sqrt(x^2+y^2)";
  const TypedDiscreteLagrangian dl("(q1-q0)^2/(2*h) - h*(V(q0)+V(q1))/2", potential);
  const TypedDiscreteLagrangian midpoint(kCases[1].ld, potential);
  const CompiledDiscreteLagrangian<2> native(dl), interpreted(dl, false), cm(midpoint, false);
  CompiledDiscreteLagrangian<2> uncarried(dl);
  uncarried.carry_over(false);
  lock.unlock();
  CHECK(native.jacobian_constant());
  CHECK_FALSE(cm.jacobian_constant());  // the midpoint rule's D2 D1 L_d depends on q_(k+1)
  CHECK(native.stats().carried > 0);
  CHECK(native.stats().newton_prefix_carried < native.stats().newton_prefix);

  // The same tape stepped by newton_solve (a Jacobian at every iterate): what the affine
  // solve must reproduce to the bit.
  struct AsNonlinear {
    CompiledDiscreteLagrangian<2> c;
    void newton_parts(const Vec<double, 2>& q0, const Vec<double, 2>& q1, double h,
                      Vec<double, 2>& D1, Mat<double, 2>& D12, bool with_jacobian = true) const {
      c.newton_parts(q0, q1, h, D1, D12, with_jacobian);
    }
    Vec<double, 2> d2(const Vec<double, 2>& q0, const Vec<double, 2>& q1, double h) const {
      return c.d2(q0, q1, h);
    }
    bool jacobian_constant() const { return false; }
  };

  const auto Ld = dl.bind<2>();
  DelIntegrator<2, decltype(Ld)> reference(Ld);
  DelIntegrator<2, CompiledDiscreteLagrangian<2>> a(native), b(interpreted), c(uncarried);
  DelIntegrator<2, AsNonlinear> d(AsNonlinear{native});
  Vec<double, 2> qr(0.5, 0.0), pr(0.0, std::sqrt(3.0));
  Vec<double, 2> qa = qr, pa = pr, qb = qr, pb = pr, qc = qr, pc = pr, qd = qr, pd = pr;
  double worst = 0;
  bool same_bits = true;
  int more_iterations = 0;
  for (int k = 0; k < 2000; ++k) {
    const SolveReport r = reference.step(qr, pr, 0.01);
    const SolveReport s = a.step(qa, pa, 0.01);
    b.step(qb, pb, 0.01);
    c.step(qc, pc, 0.01);
    const SolveReport t = d.step(qd, pd, 0.01);
    CHECK(s.iterations == t.iterations);
    CHECK(s.converged);
    CHECK(s.residual <= 1e-12);
    if (s.iterations > r.iterations) ++more_iterations;
    worst =
        std::max(worst, (qr - qa).lpNorm<Eigen::Infinity>() + (pr - pa).lpNorm<Eigen::Infinity>());
    // Carried or computed, native or interpreted, one factorisation or one per iterate: the
    // same numbers.
    same_bits = same_bits && qa == qb && pa == pb && qa == qc && pa == pc && qa == qd && pa == pd;
  }
  CHECK(more_iterations == 0);
  CHECK(same_bits);
  // Round-off apart from Newton on AutoDiff (a different method differs by O(h²) = 1e-4).
  CHECK(worst <= 1e-11);
  CHECK(worst > 0);
}

TEST_CASE("tape: evaluated in long double and double-double") {
  std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
  const TypedDiscreteLagrangian dl(kCases[0].ld, kCases[0].potential);
  const CompiledDiscreteLagrangian<2> c(dl);
  const Vec<double, 2> a(0.3, -0.2), b(0.35, -0.1);
  const double h = 0.07;
  const auto d = c.evaluate<double>(a, b, h);
  const auto l =
      c.evaluate<long double>(a.cast<long double>(), b.cast<long double>(), (long double)h);
  const auto q = c.evaluate<dd_real>(a.cast<dd_real>(), b.cast<dd_real>(), dd_real(h));
  // The value in double-double: the tree evaluator's operations, in double-double.
  const dd_real tree = dl.evaluate<2, dd_real>(a.cast<dd_real>(), b.cast<dd_real>(), dd_real(h));
  CHECK(to_double(q.value - tree) == 0.0);
  // Wider types agree with double to double's round-off, and with each other to long
  // double's (the wider result is the more accurate one).
  const double scale = 1 + d.D12.lpNorm<Eigen::Infinity>();
  for (int i = 0; i < 2; ++i) {
    CHECK(std::abs(double(l.D1(i)) - d.D1(i)) <= 16 * kEps * scale);
    CHECK(std::abs(to_double(q.D1(i)) - double(l.D1(i))) <= 1e-17 * scale);
    for (int j = 0; j < 2; ++j)
      CHECK(std::abs(to_double(q.D12(i, j)) - double(l.D12(i, j))) <= 1e-17 * scale);
  }
}

TEST_CASE("tape: native code is the interpreter's to the bit, cached, and optional") {
  std::unique_lock<std::recursive_mutex> lock(modified::ginac_mutex());
  const TypedDiscreteLagrangian dl(kCases[3].ld, kCases[3].potential);  // sin, exp, log, cos
  const CompiledDiscreteLagrangian<2> native(dl), again(dl), interpreted(dl, false);
  lock.unlock();
  CHECK_FALSE(interpreted.native());
  if (!native_expected()) return;
  INFO("native code: ", native.native_reason());
  REQUIRE(native.native());
  CHECK(again.native_path() == native.native_path());  // from the cache, not compiled twice
  for (int k = 0; k < 20; ++k) {
    const Vec<double, 2> a(0.2 + 0.05 * k, -0.3 + 0.02 * k), b(a(0) + 0.03, a(1) - 0.01 * k);
    const double h = 0.01 + 0.004 * k;
    Vec<double, 2> F1, F2;
    Mat<double, 2> J1, J2;
    native.newton_parts(a, b, h, F1, J1);
    interpreted.newton_parts(a, b, h, F2, J2);
    CHECK(F1 == F2);
    CHECK(J1 == J2);
    CHECK(native.d2(a, b, h) == interpreted.d2(a, b, h));
  }
  // Outside the domain (log of a negative number): NaN in both, never a number in one.
  const Vec<double, 2> bad(-3.0, 0.0);
  Vec<double, 2> F1, F2;
  Mat<double, 2> J1, J2;
  native.newton_parts(bad, bad, 0.1, F1, J1);
  interpreted.newton_parts(bad, bad, 0.1, F2, J2);
  for (int i = 0; i < 2; ++i) CHECK(std::isnan(F1(i)) == std::isnan(F2(i)));

  SUBCASE("without a compiler the tape is interpreted, and says why") {
    const char* old = std::getenv("VIBOOK_CC");
    const std::string saved = old ? old : "";
    const bool had = old != nullptr;
    setenv("VIBOOK_CC", "/nonexistent/vibook-cc", 1);
    setenv("VIBOOK_CACHE_DIR", (test_cache.dir + "/other").c_str(), 1);
    std::unique_lock<std::recursive_mutex> relock(modified::ginac_mutex());
    const CompiledDiscreteLagrangian<2> fallback(dl);
    relock.unlock();
    if (had)
      setenv("VIBOOK_CC", saved.c_str(), 1);
    else
      unsetenv("VIBOOK_CC");
    setenv("VIBOOK_CACHE_DIR", test_cache.dir.c_str(), 1);
    CHECK_FALSE(fallback.native());
    CHECK(fallback.native_reason().find("no C compiler") != std::string::npos);
    Vec<double, 2> F3;
    Mat<double, 2> J3;
    const Vec<double, 2> a(0.2, -0.3), b(0.25, -0.28);
    fallback.newton_parts(a, b, 0.05, F3, J3);
    interpreted.newton_parts(a, b, 0.05, F2, J2);
    CHECK(F3 == F2);
  }
}
