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

}  // namespace

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
