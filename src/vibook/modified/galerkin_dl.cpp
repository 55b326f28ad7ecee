// The Galerkin discrete Lagrangian on the engine's symbols (galerkin_dl.hpp): Marsden & West
// 2001, §2.6, with the closed-form Gauss–Legendre and Gauss–Lobatto rules.
#include "vibook/modified/galerkin_dl.hpp"

#include <stdexcept>

#include "vibook/core/errors.hpp"

namespace vibook::modified {

namespace {

ex half_plus(int sign, const ex& r) { return GiNaC::numeric(1, 2) + sign * r; }

}  // namespace

std::optional<ExactQuadrature> exact_quadrature(const std::string& family, int s) {
  using GiNaC::numeric;
  using GiNaC::sqrt;
  ExactQuadrature q;
  if (family == "gauss") {
    // roots of P_s(2c − 1)
    if (s == 1) {
      q.c = {numeric(1, 2)};
      q.b = {1};
    } else if (s == 2) {
      const ex r = sqrt(ex(3)) / 6;
      q.c = {half_plus(-1, r), half_plus(1, r)};
      q.b = {numeric(1, 2), numeric(1, 2)};
    } else if (s == 3) {
      const ex r = sqrt(ex(15)) / 10;
      q.c = {half_plus(-1, r), numeric(1, 2), half_plus(1, r)};
      q.b = {numeric(5, 18), numeric(4, 9), numeric(5, 18)};
    } else {
      return std::nullopt;
    }
  } else if (family == "lobatto") {
    // 0, 1 and the roots of P'_{s−1}(2c − 1)
    if (s == 2) {
      q.c = {0, 1};
      q.b = {numeric(1, 2), numeric(1, 2)};
    } else if (s == 3) {
      q.c = {0, numeric(1, 2), 1};
      q.b = {numeric(1, 6), numeric(2, 3), numeric(1, 6)};
    } else if (s == 4) {
      const ex r = sqrt(ex(5)) / 10;
      q.c = {0, half_plus(-1, r), half_plus(1, r), 1};
      q.b = {numeric(1, 12), numeric(5, 12), numeric(5, 12), numeric(1, 12)};
    } else if (s == 5) {
      const ex r = sqrt(ex(21)) / 14;
      q.c = {0, half_plus(-1, r), numeric(1, 2), half_plus(1, r), 1};
      q.b = {numeric(1, 20), numeric(49, 180), numeric(16, 45), numeric(49, 180), numeric(1, 20)};
    } else {
      return std::nullopt;
    }
  } else {
    return std::nullopt;
  }
  return q;
}

namespace {

template <int N>
SymbolicDL galerkin_dl_n(const ExactQuadrature& rule, const SymbolicLagrangian& L,
                         std::shared_ptr<JetSpace> jets, std::string description) {
  const int s = static_cast<int>(rule.c.size());
  // ℓ_ν(c_i) and ℓ'_ν(c_i) of the Lagrange basis on the control times ν/s, exactly.
  const GiNaC::symbol tau("tau");
  std::vector<std::vector<ex>> ell(s, std::vector<ex>(s + 1)), dell = ell;
  for (int nu = 0; nu <= s; ++nu) {
    ex l = 1;
    for (int mu = 0; mu <= s; ++mu)
      if (mu != nu) l *= (tau - GiNaC::numeric(mu, s)) / GiNaC::numeric(nu - mu, s);
    const ex dl = l.diff(tau);
    for (int i = 0; i < s; ++i) {
      ell[i][nu] = GiNaC::expand(l.subs(tau == rule.c[i]));
      dell[i][nu] = GiNaC::expand(dl.subs(tau == rule.c[i]));
    }
  }
  std::vector<GiNaC::numeric> at;
  for (int nu = 1; nu < s; ++nu) at.emplace_back(nu, s);
  const auto dl = [&](const Vec<ex, N>& q0, const std::vector<Vec<ex, N>>& Q, const Vec<ex, N>& q1,
                      const ex& h) {
    auto point = [&](int nu) -> const Vec<ex, N>& {
      return nu == 0 ? q0 : nu == s ? q1 : Q[static_cast<std::size_t>(nu - 1)];
    };
    ex sum = 0;
    for (int i = 0; i < s; ++i) {
      std::vector<ex> x(N, ex(0)), v(N, ex(0));
      for (int nu = 0; nu <= s; ++nu)
        for (int k = 0; k < N; ++k) {
          x[k] += ell[i][nu] * point(nu)(k);
          v[k] += dell[i][nu] * point(nu)(k);
        }
      for (int k = 0; k < N; ++k) v[k] = v[k] / h;
      sum += rule.b[i] * L(x, v);
    }
    return h * sum;
  };
  return symbolic_dl_interior<N>(dl, std::move(jets), std::move(description), at,
                                 InexactLiterals::error);
}

// --- a symplectic partitioned Runge–Kutta method (galerkin_dl.hpp, prk_dl) -------------------
template <int N>
SymbolicDL prk_dl_n(const std::vector<std::vector<ex>>& a, const std::vector<ex>& b,
                    const SymbolicLagrangian& L, std::shared_ptr<JetSpace> jets,
                    std::string description) {
  const int s = static_cast<int>(b.size());
  // k: the largest weight, the first of equal ones (the weights are exact numbers)
  int k = 0;
  for (int i = 1; i < s; ++i)
    if (GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(b[i])) >
        GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(b[k])))
      k = i;
  const std::vector<GiNaC::numeric> at(static_cast<std::size_t>(s - 1), GiNaC::numeric(1, 2));
  const auto dl = [&](const Vec<ex, N>& q0, const std::vector<Vec<ex, N>>& X, const Vec<ex, N>& q1,
                      const ex& h) {
    // the stage velocities: V_j = (X_j − q0)/(h/2) for j ≠ k, V_k from the constraint
    std::vector<std::vector<ex>> V(static_cast<std::size_t>(s), std::vector<ex>(N, ex(0)));
    for (int j = 0, m = 0; j < s; ++j) {
      if (j == k) continue;
      for (int d = 0; d < N; ++d) V[j][d] = 2 * (X[static_cast<std::size_t>(m)](d) - q0(d)) / h;
      ++m;
    }
    for (int d = 0; d < N; ++d) {
      ex rest = (q1(d) - q0(d)) / h;
      for (int j = 0; j < s; ++j)
        if (j != k) rest -= b[j] * V[j][d];
      V[k][d] = rest / b[k];
    }
    ex sum = 0;
    for (int i = 0; i < s; ++i) {
      std::vector<ex> x(N);
      for (int d = 0; d < N; ++d) {
        ex y = q0(d);
        for (int j = 0; j < s; ++j) y += h * a[i][j] * V[j][d];
        x[d] = y;
      }
      sum += b[i] * L(x, V[i]);
    }
    return h * sum;
  };
  return symbolic_dl_interior<N>(dl, std::move(jets), std::move(description), at,
                                 InexactLiterals::error);
}

}  // namespace

SymbolicDL prk_dl(const std::vector<std::vector<ex>>& a, const std::vector<ex>& b,
                  const SymbolicLagrangian& L, std::shared_ptr<JetSpace> jets,
                  std::string description) {
  const std::size_t s = b.size();
  if (s == 0 || a.size() != s)
    throw std::invalid_argument("prk_dl: a tableau needs an s x s matrix a and s weights b");
  for (std::size_t i = 0; i < s; ++i) {
    if (a[i].size() != s)
      throw std::invalid_argument("prk_dl: a tableau needs an s x s matrix a and s weights b");
    if (!GiNaC::is_a<GiNaC::numeric>(b[i]) || b[i].is_zero())
      throw std::invalid_argument(
          "prk_dl: every weight b_i must be a nonzero number (a zero weight leaves its stage "
          "velocity undetermined)");
  }
  switch (jets->dofs()) {
    case 1:
      return prk_dl_n<1>(a, b, L, std::move(jets), std::move(description));
    case 2:
      return prk_dl_n<2>(a, b, L, std::move(jets), std::move(description));
    case 3:
      return prk_dl_n<3>(a, b, L, std::move(jets), std::move(description));
    default:
      throw std::invalid_argument("prk_dl: 1 to 3 degrees of freedom");
  }
}

SymbolicDL galerkin_dl(const ExactQuadrature& rule, const SymbolicLagrangian& L,
                       std::shared_ptr<JetSpace> jets, std::string description) {
  if (rule.c.empty() || rule.c.size() != rule.b.size())
    throw std::invalid_argument("galerkin_dl: a rule needs as many weights as nodes");
  switch (jets->dofs()) {
    case 1:
      return galerkin_dl_n<1>(rule, L, std::move(jets), std::move(description));
    case 2:
      return galerkin_dl_n<2>(rule, L, std::move(jets), std::move(description));
    case 3:
      return galerkin_dl_n<3>(rule, L, std::move(jets), std::move(description));
    default:
      throw std::invalid_argument("galerkin_dl: 1 to 3 degrees of freedom");
  }
}

}  // namespace vibook::modified
