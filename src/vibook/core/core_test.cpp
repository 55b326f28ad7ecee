// Doctests of core/: Newton reports and typed failures, the streaming recorder, order fits,
// the extrapolation of a sample history.
#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <sstream>

#include <doctest/doctest.h>

#include "vibook/core/extrapolate.hpp"
#include "vibook/core/newton.hpp"
#include "vibook/core/order.hpp"
#include "vibook/core/parallel.hpp"
#include "vibook/core/recorder.hpp"
#include "vibook/integrators/kernels.hpp"
#include "vibook/kepler/kepler.hpp"

using namespace vibook;

TEST_CASE("newton_solve converges, reports residual and iterations") {
  // x² = 2 componentwise, in 2-D.
  Vec<double, 2> x(1.0, 3.0);
  auto fj = [](const Vec<double, 2>& v, Vec<double, 2>& F, Mat<double, 2>& J) {
    F = v.array().square() - 2.0;
    J = (2.0 * v).asDiagonal();
  };
  const SolveReport r = newton_solve<2>(x, fj, NewtonOptions{});
  CHECK(r.converged);
  CHECK(r.iterations >= 4);
  CHECK(r.iterations <= 10);
  CHECK(r.residual <= 4 * kEps);
  CHECK(std::abs(x(0) - std::sqrt(2.0)) <= 2 * kEps);
  CHECK(std::abs(x(1) - std::sqrt(2.0)) <= 2 * kEps);
}

TEST_CASE("newton_solve fails with a typed error instead of looping or returning NaN") {
  SUBCASE("no root: x² + 1 = 0") {
    Vec<double, 1> x(0.5);
    auto fj = [](const Vec<double, 1>& v, Vec<double, 1>& F, Mat<double, 1>& J) {
      F(0) = v(0) * v(0) + 1.0;
      J(0, 0) = 2.0 * v(0);
    };
    NewtonOptions opt;
    opt.max_iterations = 30;
    try {
      newton_solve<1>(x, fj, opt, "test solve");
      FAIL("expected SolveError");
    } catch (const SolveError& e) {
      CHECK_FALSE(e.report().converged);
      CHECK(e.report().iterations <= 30);
      CHECK(std::string(e.what()).find("test solve") != std::string::npos);
    }
  }
  SUBCASE("singular Jacobian") {
    Vec<double, 1> x(0.0);
    auto fj = [](const Vec<double, 1>& v, Vec<double, 1>& F, Mat<double, 1>& J) {
      F(0) = v(0) * v(0) + 1.0;
      J(0, 0) = 2.0 * v(0);
    };
    CHECK_THROWS_AS(newton_solve<1>(x, fj, NewtonOptions{}), SolveError);
  }
  SUBCASE("non-finite residual") {
    Vec<double, 1> x(1.0);
    auto fj = [](const Vec<double, 1>&, Vec<double, 1>& F, Mat<double, 1>& J) {
      F(0) = std::numeric_limits<double>::quiet_NaN();
      J(0, 0) = 1.0;
    };
    CHECK_THROWS_AS(newton_solve<1>(x, fj, NewtonOptions{}), SolveError);
  }
}

// The stopping rule reachable from rest (chapter "Verify your own integrator", "The criteria
// of every route"): the midpoint rule's discrete Euler-Lagrange equation of a charged particle
// in a magnetic field, L = |v|^2/2 + (q1 v2 - q2 v1)/2 - |q|^2/2, from q0 = (1, 0) at rest
// (p0 = (0, 1/2)). The second component of q1 - q0 is 3e-5 and its componentwise bound
// 4u·3e-5 lies below the round-off of the equation's O(1) terms: the componentwise rule alone
// ran 50 iterations at residual 1e-15 and threw. The stagnation test ends it as converged.
TEST_CASE("newton_solve converges from rest: the stagnation test ends what round-off bounds") {
  const double h = 0.05;
  const Vec<double, 2> q0(1.0, 0.0), p0(0.0, 0.5);
  auto fj = [&](const Vec<double, 2>& q1, Vec<double, 2>& F, Mat<double, 2>& J) {
    const Vec<double, 2> m = (q0 + q1) / 2, v = (q1 - q0) / h;
    F(0) = p0(0) + h / 2 * (0.5 * v(1) - m(0)) - (v(0) - 0.5 * m(1));
    F(1) = p0(1) + h / 2 * (-0.5 * v(0) - m(1)) - (v(1) + 0.5 * m(0));
    J << -h / 4 - 1 / h, 0.5, -0.5, -h / 4 - 1 / h;
  };
  auto check = [&](auto&& solve) {
    Vec<double, 2> x = q0;
    const SolveReport r = solve(x);
    CHECK(r.converged);
    CHECK(r.iterations <= 6);
    CHECK(r.residual <= 1e-14);  // the equation's terms are O(1): its round-off
    // The solution of the linear equation, independently: F(q1) = 0 by Cramer's rule.
    Vec<double, 2> F;
    Mat<double, 2> J;
    Vec<double, 2> zero = q0;
    fj(zero, F, J);  // F affine in q1: F(q1) = F(q0) + J (q1 - q0)
    const Vec<double, 2> exact = q0 - J.inverse() * F;
    CHECK(std::abs(x(0) - exact(0)) <= 1e-15);
    CHECK(std::abs(x(1) - exact(1)) <= 1e-15 * 1.0 + 1e-12 * std::abs(exact(1)));
  };
  check(
      [&](Vec<double, 2>& x) { return newton_solve<2>(x, fj, NewtonOptions{}, "magnetic", &q0); });
  check([&](Vec<double, 2>& x) {
    return affine_newton_solve<2>(
        x,
        [&](const Vec<double, 2>& y, Vec<double, 2>& F, Mat<double, 2>& J, bool) { fj(y, F, J); },
        NewtonOptions{}, "magnetic", &q0);
  });
  // The wrong input: a system with no root still throws. The stagnation test needs two tiny,
  // non-contracting updates in a row, which a diverging or cycling iteration does not give.
  Vec<double, 1> y(0.5);
  auto noroot = [](const Vec<double, 1>& v, Vec<double, 1>& F, Mat<double, 1>& J) {
    F(0) = v(0) * v(0) + 1.0;
    J(0, 0) = 2.0 * v(0);
  };
  CHECK_THROWS_AS(newton_solve<1>(y, noroot, NewtonOptions{}), SolveError);
}

TEST_CASE("simplified_newton_solve: one Jacobian where it suffices, typed failures") {
  // x² = 2 componentwise from a close start: the frozen Jacobian contracts fast enough.
  int jacobians = 0;
  auto f = [](const Vec<double, 2>& v) { return Vec<double, 2>(v.array().square() - 2.0); };
  auto jac = [&](const Vec<double, 2>& v) {
    ++jacobians;
    return Mat<double, 2>((2.0 * v).asDiagonal());
  };
  Vec<double, 2> x(1.4, 1.42);
  const SolveReport r = simplified_newton_solve<2>(x, f, jac, NewtonOptions{});
  CHECK(r.converged);
  CHECK(std::abs(x(0) - std::sqrt(2.0)) <= 2 * kEps);
  CHECK(std::abs(x(1) - std::sqrt(2.0)) <= 2 * kEps);
  CHECK(jacobians == 1);
  // From far away the contraction of a frozen Jacobian is slow: it is refreshed.
  jacobians = 0;
  Vec<double, 2> y(10.0, 0.3);
  CHECK(simplified_newton_solve<2>(y, f, jac, NewtonOptions{}).converged);
  CHECK(std::abs(y(0) - std::sqrt(2.0)) <= 2 * kEps);
  CHECK(jacobians > 1);
  // No root: a typed error within max_iterations, naming the solve.
  Vec<double, 1> z(0.5);
  NewtonOptions opt;
  opt.max_iterations = 30;
  try {
    simplified_newton_solve<1>(
        z, [](const Vec<double, 1>& v) { return Vec<double, 1>(v(0) * v(0) + 1.0); },
        [](const Vec<double, 1>& v) { return Mat<double, 1>(2.0 * v(0)); }, opt, "test solve");
    FAIL("expected SolveError");
  } catch (const SolveError& e) {
    CHECK_FALSE(e.report().converged);
    CHECK(e.report().iterations <= 30);
    CHECK(std::string(e.what()).find("test solve") != std::string::npos);
  }
  // Singular Jacobian.
  Vec<double, 1> w(0.0);
  CHECK_THROWS_AS(
      simplified_newton_solve<1>(
          w, [](const Vec<double, 1>& v) { return Vec<double, 1>(v(0) * v(0) + 1.0); },
          [](const Vec<double, 1>& v) { return Mat<double, 1>(2.0 * v(0)); }, NewtonOptions{}),
      SolveError);
}

TEST_CASE("affine_newton_solve: newton_solve's iterates, one factorisation, two evaluations") {
  // A x = b with A well conditioned: the first update lands on the solution to round-off, the
  // second passes the stopping rule.
  Mat<double, 2> A;
  A << 4.0, 1.0, -2.0, 3.0;
  const Vec<double, 2> b(1.0, -2.0);
  int evaluations = 0, jacobians = 0;
  auto fj = [&](const Vec<double, 2>& v, Vec<double, 2>& F, Mat<double, 2>& J, bool with_j) {
    ++evaluations;
    F = A * v - b;
    if (with_j) {
      ++jacobians;
      J = A;
    }
  };
  Vec<double, 2> x(0.3, 0.7);
  Vec<double, 2> x_newton = x;
  const SolveReport r = affine_newton_solve<2>(x, fj, NewtonOptions{});
  const Vec<double, 2> exact = A.partialPivLu().solve(b);
  CHECK(r.converged);
  CHECK(r.iterations == 2);
  CHECK(evaluations == 2);
  CHECK(jacobians == 1);
  CHECK((x - exact).lpNorm<Eigen::Infinity>() <= 4 * kEps * exact.lpNorm<Eigen::Infinity>());
  // The residual of the last evaluation: round-off of A x − b.
  CHECK(r.residual <= 8 * kEps *
                          (A.lpNorm<Eigen::Infinity>() * exact.lpNorm<Eigen::Infinity>() +
                           b.lpNorm<Eigen::Infinity>()));
  // The same iterates as newton_solve, to the bit, with three evaluations and two factorisations.
  evaluations = jacobians = 0;
  const SolveReport n = newton_solve<2>(x_newton, fj, NewtonOptions{});
  CHECK(n.iterations == r.iterations);
  CHECK(x_newton == x);
  CHECK(evaluations == 3);
  CHECK(jacobians == 2);

  SUBCASE("an F that is not affine is not solved by it: a typed failure, not a wrong root") {
    // x² = 2 with the Jacobian frozen at the start converges only linearly: within 3
    // iterations the stopping rule is not met, and the failure is typed.
    auto nonlinear = [](const Vec<double, 1>& v, Vec<double, 1>& G, Mat<double, 1>& J, bool) {
      G(0) = v(0) * v(0) - 2.0;
      J(0, 0) = 2.0 * v(0);
    };
    Vec<double, 1> y(3.0);
    NewtonOptions opt;
    opt.max_iterations = 3;
    CHECK_THROWS_AS(affine_newton_solve<1>(y, nonlinear, opt, "test solve"), SolveError);
  }
  SUBCASE("singular Jacobian and non-finite residual") {
    auto singular = [](const Vec<double, 1>&, Vec<double, 1>& G, Mat<double, 1>& J, bool) {
      G(0) = 1.0;
      J(0, 0) = 0.0;
    };
    Vec<double, 1> y(0.0);
    CHECK_THROWS_AS(affine_newton_solve<1>(y, singular, NewtonOptions{}), SolveError);
    auto nan = [](const Vec<double, 1>&, Vec<double, 1>& G, Mat<double, 1>& J, bool) {
      G(0) = std::numeric_limits<double>::quiet_NaN();
      J(0, 0) = 1.0;
    };
    CHECK_THROWS_AS(affine_newton_solve<1>(y, nan, NewtonOptions{}), SolveError);
  }
}

namespace {
// SmallSystemSolve against Eigen's LU with partial pivoting on an n × n system that needs row
// interchanges (its rows reversed from a diagonally dominant matrix). The criterion: the two
// solutions agree to 64 n ε κ(A) |x|, κ the ∞-norm condition number.
template <int n>
void check_small_solve() {
  CAPTURE(n);
  Mat<double, n> A;
  Vec<double, n> b;
  for (int i = 0; i < n; ++i) {
    b(i) = std::sin(1.0 + i);
    for (int j = 0; j < n; ++j) A(n - 1 - i, j) = (i == j ? n + 1.0 : 0.0) + std::cos(3.0 * i + j);
  }
  const Vec<double, n> reference = A.partialPivLu().solve(b);
  const Vec<double, n> x = SmallSystemSolve::factor(A).solve(b);
  const Mat<double, n> inverse = A.partialPivLu().inverse();
  const double kappa =
      A.cwiseAbs().rowwise().sum().maxCoeff() * inverse.cwiseAbs().rowwise().sum().maxCoeff();
  CHECK((x - reference).template lpNorm<Eigen::Infinity>() <=
        64 * n * kEps * kappa * reference.template lpNorm<Eigen::Infinity>());
  // A deliberately wrong input: a singular matrix (two equal rows) is a typed failure of
  // Newton's method, never an update.
  Mat<double, n> S = A;
  if (n > 1)
    S.row(n - 1) = S.row(0);
  else
    S(0, 0) = 0.0;
  Vec<double, n> y = Vec<double, n>::Zero();
  auto fj = [&](const Vec<double, n>& v, Vec<double, n>& F, Mat<double, n>& J) {
    F = S * v - b;
    J = S;
  };
  CHECK_THROWS_AS((newton_solve<n, decltype(fj)&, double, SmallSystemSolve>(y, fj, {})),
                  SolveError);
}
}  // namespace

TEST_CASE("SmallSystemSolve: Eigen's LU solution to round-off for n = 1…8, singular is typed") {
  check_small_solve<1>();
  check_small_solve<2>();
  check_small_solve<3>();
  check_small_solve<4>();
  check_small_solve<5>();
  check_small_solve<6>();
  check_small_solve<7>();
  check_small_solve<8>();
}

TEST_CASE("TrajectoryRecorder: header, every K-th row, first and last always") {
  std::ostringstream out;
  TrajectoryRecorder rec(out, {"step", "x"}, 3);
  for (int k = 0; k <= 7; ++k) rec.offer(k, std::array<double, 2>{double(k), 0.5 * k});
  rec.finish();
  CHECK(out.str() == "step,x\n0,0\n3,1.5\n6,3\n7,3.5\n");
  CHECK(rec.rows_written() == 4);
  CHECK_THROWS_AS(rec.offer(8, std::array<double, 1>{1.0}), std::invalid_argument);
}

namespace {
// Counts bytes without keeping them.
class CountingBuf : public std::streambuf {
 public:
  std::size_t bytes = 0;

 protected:
  int_type overflow(int_type c) override {
    ++bytes;
    return c;
  }
  std::streamsize xsputn(const char*, std::streamsize n) override {
    bytes += static_cast<std::size_t>(n);
    return n;
  }
};
long max_rss_kib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}
}  // namespace

TEST_CASE("recorder memory is O(1) in the number of steps (1e7 Kepler steps)") {
  CountingBuf buf;
  std::ostream out(&buf);
  TrajectoryRecorder rec(out, {"step", "q1", "q2", "p1", "p2"}, 1000);
  StormerVerlet<Kepler> sv;
  State<2> s = kepler_perihelion_state(0.5);
  std::array<double, 5> row{};
  auto run = [&](long from, long to) {
    for (long k = from; k < to; ++k) {
      sv.step(s.q, s.p, 1e-3);
      row = {double(k), s.q(0), s.q(1), s.p(0), s.p(1)};
      rec.offer(k, row);
    }
  };
  run(1, 1'000'000);
  const long rss_1e6 = max_rss_kib();
  run(1'000'000, 10'000'000);
  rec.finish();
  const long rss_1e7 = max_rss_kib();
  CHECK(rec.rows_written() == 10'000);
  CHECK(buf.bytes > 0);
  // Ten times the steps, the same memory: growth under 1 MiB (a stored trajectory of 9e6
  // states would need 360 MB).
  CHECK(rss_1e7 - rss_1e6 < 1024);
}

TEST_CASE("fit_order recovers a known power and excludes the round-off plateau") {
  std::vector<double> h, e;
  for (int k = 1; k <= 12; ++k) {
    h.push_back(std::ldexp(1.0, -k));
    e.push_back(std::max(3.0 * std::pow(h.back(), 2), 1e-6));  // plateau below 1e-6
  }
  const OrderFit f = fit_order(h, e, 2e-6);
  CHECK(std::abs(f.slope - 2.0) < 1e-12);
  CHECK(f.points == 10);  // h = 2^-11, 2^-12 sit on the plateau
  CHECK_THROWS_AS(fit_order(h, e, 1.0), std::invalid_argument);
}

TEST_CASE("parallel_for runs every task and rethrows the first failure") {
  std::vector<int> done(100, 0);
  vibook::parallel_for(done.size(), 2, [&](std::size_t i) { done[i] = int(i); });
  for (std::size_t i = 0; i < done.size(); ++i) CHECK(done[i] == int(i));
  std::atomic<int> ran{0};
  CHECK_THROWS_WITH_AS(vibook::parallel_for(10, 3,
                                            [&](std::size_t i) {
                                              ++ran;
                                              if (i == 4 || i == 7)
                                                throw std::runtime_error(std::to_string(i));
                                            }),
                       "4", std::runtime_error);
  CHECK(ran == 10);
}

TEST_CASE(
    "SampleHistory: exact on polynomials, the same after many pushes, next_after = push + next") {
  // The polynomial of degree n − 1 through n samples is exact on a polynomial of that degree:
  // a cubic at the integers, with small integer values, is extrapolated without rounding by
  // n = 4 and by n = 8 (its higher differences vanish), across many wraps of the buffer.
  auto cubic = [](double k) { return 2 * k * k * k - 3 * k * k + k - 5; };
  SampleHistory<double, double, 8> h;
  for (int k = 0; k < 100; ++k) {
    h.push(cubic(k));
    CHECK(h.count() == std::min(k + 1, 8));
    CHECK(h.newest() == cubic(k));
    if (k >= 7) {
      CHECK(h.next(4) == cubic(k + 1));
      CHECK(h.next() == cubic(k + 1));
      for (int j = 0; j < 8; ++j) CHECK(h.value(j) == cubic(k - j));
    }
  }
  // next_after(x) is next() after push(x) to the last bit, for values that do round, at
  // every fill level and after clear().
  SampleHistory<Vec<double, 2>, double, 8> a, b;
  for (int k = 0; k < 40; ++k) {
    if (k == 23) a.clear(), b.clear();
    const Vec<double, 2> x(std::sin(0.37 * k) / 3, std::exp(0.01 * k) / 7);
    const Vec<double, 2> predicted = a.next_after(x);
    b.push(x);
    const Vec<double, 2> pushed = b.next();
    CHECK(predicted(0) == pushed(0));
    CHECK(predicted(1) == pushed(1));
    a.push(x);
  }
}
