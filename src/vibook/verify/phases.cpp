// The criteria every route of `vibook verify` judges by (phases.hpp); chapter "Verify your own
// integrator", section "The criteria of every route".
#include "vibook/verify/phases.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "vibook/core/errors.hpp"

namespace vibook::verify {

using nlohmann::json;

namespace {

constexpr double kU = std::numeric_limits<double>::epsilon() / 2;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Eigen::MatrixXd omega(Eigen::Index n) {
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  W.topRightCorner(n, n) = Eigen::MatrixXd::Identity(n, n);
  W.bottomLeftCorner(n, n) = -Eigen::MatrixXd::Identity(n, n);
  return W;
}

// Measure `at(h)` -> (defect, resolution) at h·2^k, k < sizes: the first size must succeed
// (its NumericalError propagates), a later failure leaves that size out.
template <class At>
ScalingJudgement scan(double h, int sizes, At&& at) {
  ScalingJudgement j;
  for (int k = 0; k < sizes; ++k) {
    const double hk = h * std::exp2(k);
    j.h.push_back(hk);
    try {
      const auto [d, r] = at(hk);
      if (!std::isfinite(d) || !std::isfinite(r)) throw NumericalError("the defect is not finite");
      j.defect.push_back(d);
      j.resolution.push_back(r);
      j.error.emplace_back();
    } catch (const NumericalError& e) {
      if (k == 0) throw;
      j.defect.push_back(kNaN);
      j.resolution.push_back(kNaN);
      j.error.emplace_back(e.what());
    }
  }
  return judge_scaling(j);
}

// The round-off resolution of a defect of two steps: 2^12 u max(1, |J|_max).
double two_step_resolution(const Step& step, const Eigen::VectorXd& z, double h) {
  const Eigen::MatrixXd J = step_jacobian(step, z, h);
  if (!J.allFinite()) throw NumericalError("the Jacobian of the map is not finite");
  return 4096 * kU * std::max(1.0, J.lpNorm<Eigen::Infinity>());
}

}  // namespace

ScalingJudgement& judge_scaling(ScalingJudgement& j) {
  // The largest resolved step size, and the smallest step size measured.
  int largest = -1, smallest = -1;
  for (std::size_t k = 0; k < j.h.size(); ++k) {
    if (!std::isfinite(j.defect[k])) continue;
    if (smallest < 0) smallest = int(k);
    if (j.defect[k] > j.resolution_factor * j.resolution[k]) largest = int(k);
  }
  j.resolved = largest >= 0;
  if (!j.resolved) {
    j.passed = true;
    double worst = 0;
    for (std::size_t k = 0; k < j.h.size(); ++k)
      if (std::isfinite(j.resolution[k])) worst = std::max(worst, j.resolution[k]);
    j.why = fmt::format("no defect above {:g} x its resolution (at most {:.1e})",
                        j.resolution_factor, worst);
    return j;
  }
  const auto s = std::size_t(smallest), l = std::size_t(largest);
  if (l == s) {
    // Resolved at the smallest step only (the larger ones failed): no growth to read; a
    // resolved defect at the smallest step is a defect.
    j.passed = false;
    j.why = fmt::format(
        "defect {:.2e} at h = {:g}, {:.0f} x its resolution; no larger step to "
        "read its growth",
        j.defect[s], j.h[s], j.defect[s] / j.resolution[s]);
    return j;
  }
  const double base = std::max(j.defect[s], j.resolution[s]);
  j.growth = std::log2(j.defect[l] / base) / std::log2(j.h[l] / j.h[s]);
  j.passed = !(j.growth >= j.growth_threshold);
  j.why = fmt::format(
      "resolved at h = {:g} ({:.2e}, {:.0f} x its resolution); from h = {:g} it grows at least "
      "like h^{:.2f} ({} h^{:g})",
      j.h[l], j.defect[l], j.defect[l] / j.resolution[l], j.h[s], j.growth,
      j.passed ? "slower than" : "at least", j.growth_threshold);
  return j;
}

std::string ScalingJudgement::shown() const {
  std::vector<std::string> v;
  for (std::size_t k = 0; k < h.size(); ++k)
    v.push_back(std::isfinite(defect[k]) ? fmt::format("h = {:g}: {:.1e}", h[k], defect[k])
                                         : fmt::format("h = {:g}: no step", h[k]));
  return fmt::format("{}", fmt::join(v, ", "));
}

json ScalingJudgement::to_json() const {
  json per = json::array();
  for (std::size_t k = 0; k < h.size(); ++k) {
    json e = {{"h", h[k]},
              {"defect", std::isfinite(defect[k]) ? json(defect[k]) : json(nullptr)},
              {"resolution", std::isfinite(resolution[k]) ? json(resolution[k]) : json(nullptr)}};
    if (!error[k].empty()) e["error"] = error[k];
    per.push_back(e);
  }
  double worst = 0;
  for (double d : defect)
    if (std::isfinite(d)) worst = std::max(worst, d);
  return {{"defect", worst},
          {"by_step_size", per},
          {"resolved", resolved},
          {"growth_exponent", std::isfinite(growth) ? json(growth) : json(nullptr)},
          {"criterion",
           fmt::format("NO when resolved (defect > {:g} x resolution) and growing at least like "
                       "h^{:g}",
                       resolution_factor, growth_threshold)},
          {"why", why},
          {"passed", passed}};
}

void reverse_momenta(Eigen::VectorXd& z) {
  const Eigen::Index n = z.size() / 2;
  z.segment(n, n) *= -1;
  if (z.size() > 2 * n) z(2 * n) *= -1;
}

namespace {

// Φ'(z)·U by fourth-order central differences along each column of U (unit vectors), the
// increment delta·max(1, |z|_max).
Eigen::MatrixXd step_jacobian_along(const Step& step, const Eigen::VectorXd& z, double h,
                                    const Eigen::MatrixXd& U, double delta) {
  const double d = delta * std::max(1.0, z.lpNorm<Eigen::Infinity>());
  Eigen::MatrixXd JU(z.size(), U.cols());
  for (Eigen::Index j = 0; j < U.cols(); ++j) {
    auto at = [&](double s) {
      Eigen::VectorXd w = z + s * d * U.col(j);
      step(w, h);
      return w;
    };
    JU.col(j) = central_difference(at, d);
  }
  return JU;
}

}  // namespace

ScalingJudgement symplecticity_by_scaling(const Step& step,
                                          const std::vector<Eigen::VectorXd>& states, double h,
                                          int sizes, const TangentBasis& tangent) {
  ScalingJudgement j = scan(h, sizes, [&](double hk) {
    double d = 0, r = 0;
    for (const auto& z : states) {
      if (tangent) {  // the map restricted to the constraint manifold
        const Eigen::Index n = z.size() / 2;
        const Eigen::MatrixXd W = omega(n), U = tangent(z);
        const Eigen::MatrixXd JU = step_jacobian_along(step, z, hk, U, 1e-3);
        const Eigen::MatrixXd JU2 = step_jacobian_along(step, z, hk, U, 2e-3);
        if (!JU.allFinite() || !JU2.allFinite())
          throw NumericalError("the Jacobian of the map is not finite");
        const double size = std::max(1.0, JU.lpNorm<Eigen::Infinity>());
        d = std::max(d,
                     (JU.transpose() * W * JU - U.transpose() * W * U).lpNorm<Eigen::Infinity>() /
                         (size * size));
        r = std::max(
            r, std::max(1024 * kU, 4 * double(n) * (JU - JU2).lpNorm<Eigen::Infinity>() / size));
        continue;
      }
      // the time-t map's Jacobian in (q, p) when z = (q, p, t) carries the clock
      const Eigen::Index n = z.size() / 2;
      const Eigen::MatrixXd W = omega(n);
      const Eigen::MatrixXd J = step_jacobian(step, z, hk, 1e-3).topRows(2 * n);
      const Eigen::MatrixXd J2 = step_jacobian(step, z, hk, 2e-3).topRows(2 * n);
      if (!J.allFinite() || !J2.allFinite())
        throw NumericalError("the Jacobian of the map is not finite");
      const double size = std::max(1.0, J.lpNorm<Eigen::Infinity>());
      d = std::max(d, (J.transpose() * W * J - W).lpNorm<Eigen::Infinity>() / (size * size));
      r = std::max(r,
                   std::max(1024 * kU, 4 * double(n) * (J - J2).lpNorm<Eigen::Infinity>() / size));
    }
    return std::pair{d, r};
  });
  // A Jacobian that two increments do not agree on to kMaxResolution cannot certify anything:
  // the map is not smooth at the scale of the increment, or not a function of the state alone
  // (a stepper that carries a value from call to call). A smooth map's resolution is 1e-12 to
  // 1e-9; a solver's tolerance of 1e-10 makes it about 1e-7.
  for (std::size_t k = 0; k < j.h.size(); ++k)
    if (std::isfinite(j.resolution[k]) && j.resolution[k] > kMaxResolution) {
      j.passed = false;
      j.why = fmt::format(
          "the Jacobian cannot be measured: at h = {:g} the difference quotients at two "
          "increments disagree by {:.1e} (more than {:.0e}): the map is not smooth, or not a "
          "function of the state alone",
          j.h[k], j.resolution[k], kMaxResolution);
      break;
    }
  return j;
}

namespace {

// |A(Φ_h(z)) − z| / max(1, |z|) over the states, A the second map; with its resolution.
template <class Second>
ScalingJudgement two_steps(const Step& step, const std::vector<Eigen::VectorXd>& states, double h,
                           int sizes, Second&& second) {
  return scan(h, sizes, [&](double hk) {
    double d = 0, r = 0;
    for (const auto& z0 : states) {
      Eigen::VectorXd z = z0;
      step(z, hk);
      second(z, hk);
      if (!z.allFinite()) throw NumericalError("the state is not finite");
      d = std::max(
          d, (z - z0).lpNorm<Eigen::Infinity>() / std::max(1.0, z0.lpNorm<Eigen::Infinity>()));
      r = std::max(r, two_step_resolution(step, z0, hk));
    }
    return std::pair{d, r};
  });
}

}  // namespace

ScalingJudgement symmetry_by_scaling(const Step& step, const std::vector<Eigen::VectorXd>& states,
                                     double h, int sizes) {
  return two_steps(step, states, h, sizes, [&](Eigen::VectorXd& z, double hk) { step(z, -hk); });
}

ScalingJudgement reversibility_by_scaling(const Step& step,
                                          const std::vector<Eigen::VectorXd>& states, double h,
                                          int sizes) {
  return two_steps(step, states, h, sizes, [&](Eigen::VectorXd& z, double hk) {
    reverse_momenta(z);
    step(z, hk);
    reverse_momenta(z);
  });
}

ScalingJudgement constraint_by_scaling(const Step& step, const Eigen::VectorXd& z0, double h,
                                       long long steps, const Observable& residual, int sizes) {
  return scan(h, sizes, [&](double hk) {
    Eigen::VectorXd z = z0;
    double worst = residual(z), size = std::max(1.0, z.lpNorm<Eigen::Infinity>());
    for (long long k = 0; k < steps; ++k) {
      step(z, hk);
      if (!z.allFinite()) throw NumericalError("the state is not finite");
      worst = std::max(worst, residual(z));
      size = std::max(size, z.lpNorm<Eigen::Infinity>());
    }
    return std::pair{worst, 1024 * kU * size * size};
  });
}

ReversingSymmetry momentum_reversal(const Observable& H,
                                    const std::vector<Eigen::VectorXd>& states) {
  for (const auto& z0 : states)
    for (double scale : {1.0, 0.5, 2.0}) {
      const Eigen::Index n = z0.size() / 2;
      Eigen::VectorXd z = z0;
      z.segment(n, n) *= scale;
      Eigen::VectorXd r = z;
      reverse_momenta(r);
      double a = kNaN, b = kNaN;
      try {
        a = H(z);
        b = H(r);
      } catch (const NumericalError&) {
        continue;  // a state where the energy is not defined says nothing
      }
      if (!std::isfinite(a) || !std::isfinite(b)) continue;
      if (std::abs(a - b) > 1e-12 * std::max(1.0, std::abs(a))) {
        std::vector<double> q(z.data(), z.data() + n), p(z.data() + n, z.data() + 2 * n);
        if (z.size() > 2 * n)
          return {false, fmt::format("H(q, -p, -t) = {:.6g} differs from H(q, p, t) = {:.6g} at "
                                     "q = ({}), p = ({}), t = {}",
                                     b, a, fmt::join(q, ", "), fmt::join(p, ", "), z(2 * n))};
        return {false, fmt::format("H(q, -p) = {:.6g} differs from H(q, p) = {:.6g} at q = "
                                   "({}), p = ({})",
                                   b, a, fmt::join(q, ", "), fmt::join(p, ", "))};
      }
    }
  if (!states.empty() && states.front().size() % 2)
    return {true, "H(q, -p, -t) = H(q, p, t) at the sample states"};
  return {true, "H(q, -p) = H(q, p) at the sample states"};
}

ConsistencyJudgement judge_consistency(double conditions_order, double measured) {
  if (std::isfinite(conditions_order) && conditions_order < 1)
    return {false, fmt::format("not consistent: its exact conditions give order {:g} (below 1)",
                               conditions_order)};
  if (std::isfinite(measured) && measured < 0.5)
    return {false,
            fmt::format("not consistent: measured order {:.3f} (below 1/2: the error does not "
                        "vanish with h)",
                        measured)};
  return {true, std::isfinite(measured)
                    ? fmt::format("measured order {:.3f} >= 1/2{}", measured,
                                  std::isfinite(conditions_order)
                                      ? fmt::format(", conditions give {:g}", conditions_order)
                                      : std::string())
                    : std::string("no measured order to judge")};
}

}  // namespace vibook::verify
