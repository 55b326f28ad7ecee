// The modified-equation engine: Vermeeren 2017 §3.2 (direct route), §4.2 (13) and Lemma 6 /
// Definition 6 (meshed modified Lagrangian), §4.6 (recursive elimination), Definition 8
// (modified Lagrangian); the series Legendre transform of §5.2; Shen & Sun 2025 §4.
#include "vibook/modified/engine.hpp"

#include <array>
#include <cstdio>
#include <sstream>

#include "vibook/core/progress.hpp"
#include "vibook/integrators/splitting.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"
#include "vibook/problems/problems.hpp"

namespace vibook::modified {

void apply_inexact_policy(const SymbolicDL& dl, InexactLiterals policy) {
  if (dl.inexact_literals.empty() || policy == InexactLiterals::collect) return;
  if (policy == InexactLiterals::error) {
    std::string more;
    if (dl.inexact_literals.size() > 1)
      more = " (and " + std::to_string(dl.inexact_literals.size() - 1) + " more)";
    throw ArgumentError("discrete Lagrangian '" + dl.description + "'",
                        dl.inexact_literals.front() + more);
  }
  for (const auto& w : dl.inexact_literals)
    std::fprintf(stderr, "vibook: warning: discrete Lagrangian '%s': %s\n", dl.description.c_str(),
                 w.c_str());
}

using GiNaC::numeric;
using SubsMap = std::map<ex, Series, GiNaC::ex_is_less>;

std::recursive_mutex& ginac_mutex() {
  static std::recursive_mutex m;
  return m;
}

// ---------------------------------------------------------------------------------------------
// Parsing
// ---------------------------------------------------------------------------------------------

Method parse_method(const std::string& s) {
  if (s == "sv") return Method::sv;
  if (s == "se") return Method::se;
  if (s == "se-adjoint") return Method::se_adjoint;
  if (s == "midpoint") return Method::midpoint;
  if (s == "vi1") return Method::vi1;
  if (s == "vi1-adjoint") return Method::vi1_adjoint;
  if (s == "vi2") return Method::vi2;
  throw ArgumentError("--method", "unknown method '" + s +
                                      "' (sv, se, se-adjoint, midpoint, vi1, vi1-adjoint, vi2)");
}

Potential parse_potential(const std::string& s) {
  if (s == "generic") return Potential::generic;
  if (s == "kepler") return Potential::kepler;
  if (s == "pendulum") return Potential::pendulum;
  if (s == "harmonic") return Potential::harmonic;
  throw ArgumentError("--potential",
                      "unknown potential '" + s + "' (generic, kepler, pendulum, harmonic)");
}

Format parse_format(const std::string& s) {
  if (s == "text") return Format::text;
  if (s == "latex") return Format::latex;
  if (s == "python") return Format::python;
  throw ArgumentError("--format", "unknown format '" + s + "' (text, latex, python)");
}

// ---------------------------------------------------------------------------------------------
// Discrete Lagrangians from the integrators' templates
// ---------------------------------------------------------------------------------------------

namespace {

// Shen & Sun (3.3): the pieces φ^[i] of a splitting, as symbolic expressions.
template <int N_, class Problem>
struct WeightedExprSplit {
  static constexpr int N = N_;
  Problem problem;
  std::array<ex, N_> weight;
  template <class S>
  S piece(int i, const Vec<S, N>& x) const {
    return weight[i] * problem.potential(x);
  }
};
template <int N_>
struct AbstractSplit {
  static constexpr int N = N_;
  std::array<int, N_> family;
  template <class S>
  S piece(int i, const Vec<S, N>& x) const {
    return AbstractPotential<N>{family[i]}.potential(x);
  }
};

template <int N, class Problem, class Split>
SymbolicDL build(Method m, const Problem& P, const Split& split, std::shared_ptr<JetSpace> J,
                 const std::string& what) {
  const auto L = mechanical_lagrangian(P);
  switch (m) {
    case Method::sv:
      return symbolic_dl<N>(stormer_verlet_dl(L), J, "Störmer–Verlet, " + what);
    case Method::se:
      return symbolic_dl<N>(symplectic_euler_dl(L), J, "symplectic Euler (L(x1, v)), " + what);
    case Method::se_adjoint:
      return symbolic_dl<N>(symplectic_euler_adjoint_dl(L), J,
                            "symplectic Euler adjoint (L(x0, v)), " + what);
    case Method::midpoint:
      return symbolic_dl<N>(midpoint_dl(L), J, "midpoint, " + what);
    case Method::vi1:
      return symbolic_dl<N>(splitting_dl(split), J, "VI-1 (3.3), " + what);
    case Method::vi1_adjoint:
      return symbolic_dl<N>(splitting_dl_adjoint(split), J, "VI-1 adjoint, " + what);
    case Method::vi2: {
      // Shen & Sun (3.8): L_d*(x_n, x_{n+1/2}, h/2) + L_d^{1st}(x_{n+1/2}, x_{n+1}, h/2), the
      // two templates SplittingVariational composes.
      auto first = splitting_dl(split);
      auto adjoint = splitting_dl_adjoint(split);
      auto three = [first, adjoint](const auto& a, const auto& m, const auto& b,
                                    const auto& h) -> ex {
        const ex half = h / 2;
        return adjoint(a, m, half) + first(m, b, half);
      };
      return symbolic_dl3<N>(three, J, "VI-2 (3.8), " + what);
    }
  }
  throw ArgumentError("--method", "unknown method");
}

template <int N>
SymbolicDL generic_dl(Method m) {
  auto J = std::make_shared<JetSpace>(N);
  const int U = J->add_family("U", "U");
  AbstractSplit<N> split{};
  for (int i = 0; i < N; ++i)
    split.family[i] =
        J->add_family("phi" + std::to_string(i + 1), "\\phi^{[" + std::to_string(i + 1) + "]}");
  const std::string what =
      "generic potential, " + std::to_string(N) + " degree" + (N == 1 ? "" : "s") + " of freedom";
  if (m == Method::vi1 || m == Method::vi1_adjoint || m == Method::vi2) {
    // U is not used: the pieces are the potential.
    return build<N>(m, AbstractPotential<N>{U}, split, J, what + " split as phi1 + phi2 + …");
  }
  return build<N>(m, AbstractPotential<N>{U}, split, J, what);
}

}  // namespace

SymbolicDL make_discrete_lagrangian(Method m, Potential p, int dim,
                                    std::optional<GiNaC::numeric> alpha) {
  const ex a = alpha ? ex(*alpha) : ex(GiNaC::symbol("alpha", "\\alpha"));
  switch (p) {
    case Potential::generic:
      if (dim == 1) return generic_dl<1>(m);
      if (dim == 2) return generic_dl<2>(m);
      if (dim == 3) return generic_dl<3>(m);
      throw ArgumentError("--dim", std::to_string(dim) +
                                       ": a generic potential has 1, 2 or 3 degrees of "
                                       "freedom");
    case Potential::kepler: {
      if (dim != 2) throw ArgumentError("--dim", "the Kepler potential is two-dimensional");
      auto J = std::make_shared<JetSpace>(2);
      WeightedExprSplit<2, Kepler> split{Kepler{}, {a, 1 - a}};
      return build<2>(m, Kepler{}, split, J, "Kepler U = −1/|x|");
    }
    case Potential::pendulum: {
      if (dim != 1) throw ArgumentError("--dim", "the pendulum is one-dimensional");
      auto J = std::make_shared<JetSpace>(1);
      WeightedExprSplit<1, Pendulum> split{Pendulum{}, {ex(1)}};
      return build<1>(m, Pendulum{}, split, J, "pendulum U = −cos x");
    }
    case Potential::harmonic: {
      if (dim != 1) throw ArgumentError("--dim", "the harmonic oscillator is one-dimensional");
      auto J = std::make_shared<JetSpace>(1);
      WeightedExprSplit<1, HarmonicOscillator> split{HarmonicOscillator{}, {ex(1)}};
      return build<1>(m, HarmonicOscillator{}, split, J, "harmonic oscillator U = x²/2");
    }
  }
  throw ArgumentError("--potential", "unknown potential");
}

// ---------------------------------------------------------------------------------------------
// The engine
// ---------------------------------------------------------------------------------------------

Engine::Engine(SymbolicDL dl, int order) : dl_(std::move(dl)), K_(order) {
  if (order < 0 || order > max_order)
    throw ArgumentError("--order", std::to_string(order) + ": supported orders are 0 to " +
                                       std::to_string(max_order));
}

GiNaC::numeric Engine::mesh_coefficient(int i) {
  // Vermeeren, Lemma 6: (2^{1−2i} − 1) B_{2i} / (2i)!
  const numeric two_pow = i == 0 ? numeric(2) : numeric(1, 1L << (2 * i - 1));
  return (two_pow - 1) * GiNaC::bernoulli(numeric(2 * i)) / GiNaC::factorial(numeric(2 * i));
}

// V (13): x(t ∓ h/2) expanded around the midpoint t, then L_disc = L_d / h.
const std::vector<ex>& Engine::l_disc() {
  if (!ldisc_.empty()) return ldisc_;
  progress::set_stage("L_disc: expanding L_d in h to h^" + std::to_string(K_));
  const JetSpace& J = *dl_.jets;
  const int P0 = K_ + 4;
  SubsMap subs;
  for (int i = 0; i < J.dofs(); ++i) {
    subs[dl_.q0[i]] = shifted_jet(J, i, numeric(-1, 2), P0);
    subs[dl_.q1[i]] = shifted_jet(J, i, numeric(1, 2), P0);
  }
  subs[J.h()] = Series::h();
  if (dl_.interior_on_curve && !dl_.qm_at.empty())
    throw std::logic_error("interior_on_curve applies to one interior node at the midpoint");
  if (!dl_.qm.empty()) {
    const auto m = dl_.interior_on_curve ? std::vector<Series>{} : interior_node(subs, K_ + 4);
    for (std::size_t i = 0; i < dl_.qm.size(); ++i)
      subs[dl_.qm[i]] = dl_.interior_on_curve ? shifted_jet(J, static_cast<int>(i), 0, P0) : m[i];
  }
  SeriesEvaluator eval(J, subs, K_ + 3);
  const Series L = eval(dl_.Ld) / Series::h();
  if (L.prec < K_ + 1)
    throw std::logic_error("the expansion of h^-1 L_d in h is known only to O(h^" +
                           std::to_string(L.prec) + "), short of the O(h^" +
                           std::to_string(K_ + 1) +
                           ") asked for: L_d has powers of h below h^1 (is L_d ≈ h·L?)");
  if (L.valuation() < 0)
    throw NumericalError(
        "the discrete Lagrangian is not consistent: L_d/h has negative powers of h");
  for (int k = 0; k <= K_; ++k) ldisc_.push_back(GiNaC::expand(L.coeff(k)));
  return ldisc_;
}

// V Definition 6 with the coefficients of Lemma 6.
const std::vector<ex>& Engine::l_mesh() {
  if (!lmesh_.empty()) return lmesh_;
  const auto& l = l_disc();
  const JetSpace& J = *dl_.jets;
  // Dl[k][r] = D^r ℓ_k
  std::vector<std::vector<ex>> Dl(K_ + 1);
  for (int k = 0; k <= K_; ++k) Dl[k].push_back(l[k]);
  for (int k = 0; k <= K_; ++k) {
    progress::set_stage("L_mesh: h^" + std::to_string(k) + " of h^" + std::to_string(K_));
    ex m = 0;
    for (int i = 0; 2 * i <= k; ++i) {
      auto& row = Dl[k - 2 * i];
      while (static_cast<int>(row.size()) <= 2 * i)
        row.push_back(GiNaC::expand(J.total(row.back())));
      m += mesh_coefficient(i) * row[2 * i];
    }
    lmesh_.push_back(GiNaC::expand(m));
  }
  return lmesh_;
}

// Marsden & West (2001) §2.3.1, the variational order. Both sides are expanded around the
// midpoint t of the step [t − h/2, t + h/2]: L_d/h = Σ h^k ℓ_k (V (13), l_disc), and the
// exact discrete Lagrangian over h, the mean of L along the solution through the step,
//   (1/h) ∫_{−h/2}^{h/2} L(x(t + s), ẋ(t + s)) ds = Σ_{j even} h^j D^j L / (2^j (j + 1)!).
// The jets x^{(ℓ)}, ℓ ≥ 2, are then those of the solutions of L: ẍ = F(x, ẋ) and its total
// derivatives (jets_along with the h-free F).
VariationalOrder Engine::variational_order(const ex& L) {
  const auto& l = l_disc();
  const JetSpace& J = *dl_.jets;
  progress::set_stage("variational order: L_d − L_d^E to h^" + std::to_string(K_ + 1));
  std::vector<ex> e;
  ex DjL = GiNaC::expand(L);
  for (int k = 0; k <= K_; ++k) {
    if (k > 0) DjL = GiNaC::expand(J.total(DjL));
    const ex mean = k % 2 == 0 ? DjL / (GiNaC::pow(numeric(2), k) * GiNaC::factorial(k + 1)) : 0;
    e.push_back(GiNaC::expand(l[k] - mean));
  }
  const auto f0 = solve_for_acceleration(euler_lagrange({L}), 0);
  std::vector<Series> F;
  for (const ex& fi : f0[0]) F.push_back(Series::constant(fi));
  std::vector<std::vector<ex>> uses;
  for (const ex& ek : e) uses.push_back({ek});
  const Series d = along(e, jets_along(F, uses, K_ + 1), K_ + 1);
  VariationalOrder out;
  out.checked = K_;
  for (int k = 0; k <= K_; ++k) {
    out.defect.push_back(GiNaC::expand(d.coeff(k)));
    if (out.order < 0 && !vanishes(out.defect.back())) out.order = k;
  }
  return out;
}

std::vector<std::vector<ex>> Engine::euler_lagrange(const std::vector<ex>& L) const {
  const JetSpace& J = *dl_.jets;
  std::vector<std::vector<ex>> E;
  for (const ex& Lk : L) {
    std::vector<ex> row;
    const int top = std::max(J.max_order(Lk), 0);
    for (int j = 0; j < J.dofs(); ++j) {
      ex acc = 0;
      for (int l = 0; l <= top; ++l) {
        ex term = J.partial(Lk, l, j);
        for (int r = 0; r < l; ++r) term = GiNaC::expand(J.total(term));
        acc += (l % 2 ? -1 : 1) * term;
      }
      row.push_back(GiNaC::expand(acc));
    }
    E.push_back(std::move(row));
  }
  return E;
}

std::vector<std::vector<ex>> Engine::euler_lagrange_two_term(const std::vector<ex>& L) const {
  const JetSpace& J = *dl_.jets;
  std::vector<std::vector<ex>> E;
  for (const ex& Lk : L) {
    std::vector<ex> row;
    for (int j = 0; j < J.dofs(); ++j)
      row.push_back(GiNaC::expand(J.partial(Lk, 0, j) - J.total(J.partial(Lk, 1, j))));
    E.push_back(std::move(row));
  }
  return E;
}

std::vector<int> Engine::solved() const {
  if (!dl_.solve_for.empty()) return dl_.solve_for;
  std::vector<int> all;
  for (int i = 0; i < dl_.jets->dofs(); ++i) all.push_back(i);
  return all;
}

std::vector<std::vector<Series>> Engine::jets_along(const std::vector<Series>& F,
                                                    const std::vector<std::vector<ex>>& uses,
                                                    int cap) const {
  const JetSpace& J = *dl_.jets;
  const std::vector<int> S = solved();
  const int ns = static_cast<int>(S.size());
  // first[ℓ]: the first power k of h whose expressions contain x^{(ℓ)}; it enters the sum
  // multiplied by h^k, so O(h^{cap−k}) of it is all that is ever used. Truncating there keeps
  // the high derivatives short (their series swell fastest: dimension 2–3, order 6–8).
  int top = 2;
  std::vector<int> first;
  for (std::size_t k = 0; k < uses.size(); ++k)
    for (const ex& e : uses[k])
      for (int d : S) {
        const int o = J.max_order(e, d);
        if (o > top) top = o;
        if (static_cast<int>(first.size()) <= o) first.resize(o + 1, cap);
        for (int l = 2; l <= o; ++l) first[l] = std::min(first[l], static_cast<int>(k));
      }
  first.resize(std::max(top, 2) + 1, cap);
  const auto level_cap = [&](int l) { return reference_ ? cap : std::max(1, cap - first[l]); };
  std::vector<bool> is_solved(J.dofs(), false);
  for (int d : S) is_solved[d] = true;
  std::vector<std::vector<Series>> out(std::max(top, 2) + 1);
  out[2] = F;
  for (int l = 3; l <= top; ++l) {
    progress::set_stage("derivatives of order " + std::to_string(l) + " of " + std::to_string(top) +
                        " along the modified equation");
    out[l].resize(ns);
    const int lcap = level_cap(l);
    for (int i = 0; i < ns; ++i) {
      // D along ẍ = F: ∂/∂x · ẋ (with the chain rule) + ∂/∂ẋ · F for the solved degrees of
      // freedom; Σ_ℓ ∂/∂x^{(ℓ)} · x^{(ℓ+1)} for the free ones.
      const Series Sl = out[l - 1][i].truncated(lcap);
      Series A;
      A.prec = Sl.prec;
      A.low = Sl.low;
      std::vector<Series> B(ns);
      for (int j = 0; j < ns; ++j) {
        B[j].prec = Sl.prec;
        B[j].low = Sl.low;
      }
      for (const ex& c : Sl.c) {
        A.c.push_back(GiNaC::expand(J.total_except(c, is_solved)));
        for (int j = 0; j < ns; ++j) B[j].c.push_back(GiNaC::expand(c.diff(J.x(1, S[j]))));
      }
      Series r = A;
      for (int j = 0; j < ns; ++j) r = r + (B[j] * F[j].truncated(lcap)).truncated(lcap);
      out[l][i] = r.truncated(lcap);
    }
  }
  return out;
}

namespace {
SubsMap jet_subs(const JetSpace& J, const std::vector<int>& S,
                 const std::vector<std::vector<Series>>& jets) {
  SubsMap subs;
  for (int l = 2; l < static_cast<int>(jets.size()); ++l)
    for (std::size_t i = 0; i < S.size(); ++i) subs[J.x(l, S[i])] = jets[l][i];
  return subs;
}

// Σ_k h^k (e[k] evaluated with subs), truncated at cap.
Series shifted_sum(const JetSpace& J, const std::vector<ex>& e, const SubsMap& subs, int cap) {
  Series out = Series::constant(0).truncated(cap);
  for (int k = 0; k < static_cast<int>(e.size()) && k < cap; ++k) {
    // e[k] enters with h^k: O(h^{cap−k}) of it is enough (and all the jets hold, see
    // jets_along).
    SeriesEvaluator eval(J, subs, J.reference() ? cap : cap - k);
    Series term = eval(e[k]);
    Series hk = Series::constant(1);
    for (int r = 0; r < k; ++r) hk = hk * Series::h();
    out = out + (hk * term).truncated(cap);
  }
  return out.truncated(cap);
}

GiNaC::matrix inverse_checked(const GiNaC::matrix& A, const char* what) {
  const ex det = GiNaC::normal(A.determinant());
  if (det.is_zero())
    throw NumericalError(std::string(what) + " is singular: the Lagrangian is not regular");
  GiNaC::matrix inv = A.inverse();
  for (unsigned i = 0; i < inv.rows(); ++i)
    for (unsigned j = 0; j < inv.cols(); ++j) inv(i, j) = GiNaC::normal(inv(i, j));
  return inv;
}
}  // namespace

Series Engine::along(const std::vector<ex>& e, const std::vector<std::vector<Series>>& jets,
                     int cap) const {
  return shifted_sum(*dl_.jets, e, jet_subs(*dl_.jets, solved(), jets), cap);
}

// V §4.6: recursive elimination. E_0 is affine in ẍ with matrix A = ∂E_0/∂ẍ; once ẍ = F is
// known to O(h^m), the h^m coefficient r_m of E along F gives f_m = −A^{-1} r_m.
std::vector<std::vector<ex>> Engine::solve_for_acceleration(const std::vector<std::vector<ex>>& E,
                                                            int order) const {
  const JetSpace& J = *dl_.jets;
  const std::vector<int> S = solved();
  const int n = static_cast<int>(S.size());
  if (E.empty()) throw std::logic_error("empty Euler–Lagrange series");
  for (int i : S)
    for (int d : S)
      if (J.max_order(E[0][i], d) > 2)
        throw NumericalError("the leading Euler–Lagrange term involves derivatives beyond ẍ");
  GiNaC::matrix A(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      A(i, j) = GiNaC::expand(E[0][S[i]].diff(J.x(2, S[j])));
      for (int l = 0; l < n; ++l)
        if (!vanishes(A(i, j).diff(J.x(2, S[l]))))
          throw NumericalError("the leading Euler–Lagrange term is not affine in ẍ");
    }
  const GiNaC::matrix Ainv = inverse_checked(A, "∂E_0/∂ẍ");
  GiNaC::exmap zero;
  for (int j = 0; j < n; ++j) zero[J.x(2, S[j])] = 0;
  std::vector<Series> F(n);
  std::vector<std::vector<ex>> f(1, std::vector<ex>(n));
  for (int i = 0; i < n; ++i) {
    ex acc = 0;
    for (int j = 0; j < n; ++j) acc -= Ainv(i, j) * E[0][S[j]].subs(zero);
    f[0][i] = GiNaC::expand(acc);
    F[i] = Series::constant(f[0][i]);  // the truncated ansatz, a polynomial in h
  }
  for (int m = 1; m <= order; ++m) {
    if (m >= static_cast<int>(E.size())) throw std::logic_error("Euler–Lagrange series too short");
    const int cap = m + 1;
    std::vector<std::vector<ex>> uses(m + 1);
    for (int k = 0; k <= m; ++k)
      for (int i : S) uses[k].push_back(E[k][i]);
    const auto jets = jets_along(F, uses, cap);
    std::vector<ex> r(n);
    for (int i = 0; i < n; ++i) {
      std::vector<ex> col;
      for (int k = 0; k <= m; ++k) col.push_back(E[k][S[i]]);
      const Series R = along(col, jets, cap);
      for (int k = 0; k < m; ++k)
        if (!vanishes(R.coeff(k)))
          throw std::logic_error("recursive elimination: h^" + std::to_string(k) +
                                 " term left over");
      r[i] = R.coeff(m);
    }
    f.emplace_back(n);
    for (int i = 0; i < n; ++i) {
      ex acc = 0;
      for (int j = 0; j < n; ++j) acc -= Ainv(i, j) * r[j];
      f[m][i] = GiNaC::expand(acc);
      F[i].c.push_back(f[m][i]);
    }
  }
  return f;
}

const std::vector<std::vector<ex>>& Engine::modified_equation() {
  if (f_.empty()) {
    const auto& lm = l_mesh();
    progress::set_stage("modified equation to h^" + std::to_string(K_) +
                        ": Euler-Lagrange equations");
    const auto E = euler_lagrange(lm);
    progress::set_stage("modified equation to h^" + std::to_string(K_) +
                        ": solving for the acceleration");
    f_ = solve_for_acceleration(E, K_);
  }
  return f_;
}

// V §3.2: Ψ = D2 L_d(x(t−h), x(t)) + D1 L_d(x(t), x(t+h)), divided by h (vibook's scaling).
std::vector<std::vector<ex>> Engine::modified_equation_direct() {
  const JetSpace& J = *dl_.jets;
  const int n = J.dofs();
  const int P0 = K_ + 5;
  SubsMap back, fwd;
  for (int i = 0; i < n; ++i) {
    back[dl_.q0[i]] = shifted_jet(J, i, -1, P0);
    back[dl_.q1[i]] = shifted_jet(J, i, 0, P0);
    fwd[dl_.q0[i]] = shifted_jet(J, i, 0, P0);
    fwd[dl_.q1[i]] = shifted_jet(J, i, 1, P0);
  }
  back[J.h()] = Series::h();
  fwd[J.h()] = Series::h();
  if (!dl_.qm.empty() && dl_.interior_on_curve)
    throw ArgumentError("--method", "the direct route needs the interior node eliminated");
  if (!dl_.qm.empty()) {  // ∂L_eff/∂q = ∂L_d/∂q at the interior node (∂L_d/∂qm = 0 there)
    const auto mb = interior_node(back, K_ + 5), mf = interior_node(fwd, K_ + 5);
    for (std::size_t i = 0; i < dl_.qm.size(); ++i) {
      back[dl_.qm[i]] = mb[i];
      fwd[dl_.qm[i]] = mf[i];
    }
  }
  std::vector<std::vector<ex>> E(K_ + 1, std::vector<ex>(n));
  for (int i = 0; i < n; ++i) {
    SeriesEvaluator eb(J, back, K_ + 3), ef(J, fwd, K_ + 3);
    const Series psi = (eb(dl_.Ld.diff(dl_.q1[i])) + ef(dl_.Ld.diff(dl_.q0[i]))) / Series::h();
    if (psi.prec < K_ + 1)
      throw std::logic_error(
          "the discrete Euler–Lagrange expression's expansion in h is known only to O(h^" +
          std::to_string(psi.prec) + "), short of the O(h^" + std::to_string(K_ + 1) +
          ") asked for: L_d has powers of h below h^1");
    if (psi.valuation() < 0)
      throw NumericalError("the discrete Euler–Lagrange expression has negative powers of h");
    for (int k = 0; k <= K_; ++k) E[k][i] = GiNaC::expand(psi.coeff(k));
  }
  return solve_for_acceleration(E, K_);
}

namespace {

// x = A⁻¹ b for a square matrix of series, by Gaussian elimination: in each column the pivot
// is the entry of lowest valuation (the first whose leading coefficient does not vanish), so
// a pivot's leading term is never a zero that only looks nonzero.
std::vector<Series> solve_series(std::vector<std::vector<Series>> A, std::vector<Series> b) {
  const std::size_t n = b.size();
  auto lead = [](const Series& s) {
    for (std::size_t k = 0; k < s.c.size() && s.low + static_cast<int>(k) < s.prec; ++k)
      if (!vanishes(s.c[k])) return s.low + static_cast<int>(k);
    return Series::exact;
  };
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t piv = n;
    int best = Series::exact;
    for (std::size_t r = k; r < n; ++r) {
      const int v = lead(A[r][k]);
      if (v < best) {
        best = v;
        piv = r;
      }
    }
    if (piv == n)
      throw NumericalError(
          "the interior points of the discrete Lagrangian could not be eliminated: "
          "∂²L_d/∂Q² is singular");
    std::swap(A[k], A[piv]);
    std::swap(b[k], b[piv]);
    for (std::size_t r = k + 1; r < n; ++r) {
      const Series f = A[r][k] / A[k][k];
      for (std::size_t c = k + 1; c < n; ++c) A[r][c] = A[r][c] - f * A[k][c];
      b[r] = b[r] - f * b[k];
    }
  }
  std::vector<Series> x(n);
  for (std::size_t k = n; k-- > 0;) {
    Series acc = b[k];
    for (std::size_t c = k + 1; c < n; ++c) acc = acc - A[k][c] * x[c];
    x[k] = acc / A[k][k];
  }
  return x;
}

}  // namespace

// Newton's method on series for ∂L_d/∂qm(q0, qm, q1, h) = 0: each step doubles the number of
// correct terms; the result is checked to vanish to the requested precision.
std::vector<Series> Engine::interior_node(const SubsMap& subs, int cap) const {
  const JetSpace& J = *dl_.jets;
  const int n = static_cast<int>(dl_.qm.size());
  std::vector<ex> G(n);
  std::vector<std::vector<ex>> H(n, std::vector<ex>(n));
  for (int i = 0; i < n; ++i) {
    G[i] = dl_.Ld.diff(dl_.qm[i]);
    for (int j = 0; j < n; ++j) H[i][j] = G[i].diff(dl_.qm[j]);
  }
  std::vector<Series> m(n);
  if (dl_.qm_at.empty()) {  // one interior node, started at the mean of q0, q1
    for (int i = 0; i < n; ++i)
      m[i] = (subs.at(dl_.q0[i]) + subs.at(dl_.q1[i])) * Series::constant(numeric(1, 2));
  } else {  // several: each on the chord q0 + τ(q1 − q0)
    for (int i = 0; i < n; ++i) {
      const int d = dl_.qm_dof[i];
      m[i] = subs.at(dl_.q0[d]) +
             (subs.at(dl_.q1[d]) - subs.at(dl_.q0[d])) * Series::constant(dl_.qm_at[i]);
    }
  }
  auto residual = [&](SubsMap& s, std::vector<Series>& g, std::vector<std::vector<Series>>* hess,
                      int at) {
    for (int i = 0; i < n; ++i) s[dl_.qm[i]] = m[i];
    SeriesEvaluator eval(J, s, at + 2);
    for (int i = 0; i < n; ++i) {
      g[i] = eval(G[i]);
      if (hess)
        for (int j = 0; j < n; ++j) (*hess)[i][j] = eval(H[i][j]);
    }
  };
  // Newton's method on series doubles the number of correct terms per step, so the early
  // steps are taken at a precision that doubles too (4, 8, … up to cap); at full precision
  // it stops when a correction vanishes. (Eight steps at full precision, as before, cost
  // 8× the two or three that are needed: 3-D, vi2.)
  int at = reference_ ? cap : std::min(cap, 4);
  for (int iter = 0; iter < (reference_ ? 8 : 12); ++iter) {
    SubsMap s = subs;
    std::vector<Series> g(n);
    std::vector<std::vector<Series>> hm(n, std::vector<Series>(n));
    residual(s, g, &hm, at);
    // δ = H⁻¹ g by cofactors (n ≤ 3), or by elimination (more interior unknowns).
    std::vector<Series> delta(n);
    if (n > 3) {
      delta = solve_series(hm, g);
    } else {
      Series det;
      std::vector<std::vector<Series>> adj(n, std::vector<Series>(n));
      if (n == 1) {
        det = hm[0][0];
        adj[0][0] = Series::constant(1);
      } else if (n == 2) {
        det = hm[0][0] * hm[1][1] - hm[0][1] * hm[1][0];
        adj = {{hm[1][1], -hm[0][1]}, {-hm[1][0], hm[0][0]}};
      } else {
        auto cof = [&](int r, int c) {
          const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
          return hm[r1][c1] * hm[r2][c2] - hm[r1][c2] * hm[r2][c1];
        };
        det = hm[0][0] * cof(0, 0) + hm[0][1] * cof(0, 1) + hm[0][2] * cof(0, 2);
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) adj[c][r] = cof(r, c);
      }
      for (int i = 0; i < n; ++i) {
        Series d = Series::constant(0);
        for (int j = 0; j < n; ++j) d = d + adj[i][j] * g[j];
        delta[i] = d / det;
      }
    }
    bool moved = false;
    for (int i = 0; i < n; ++i) {
      // The correction to O(h^at), applied as a polynomial: m stays a polynomial in h that
      // the next, more precise step refines.
      Series step = delta[i].truncated(at);
      for (int k = step.valuation(); k < step.prec; ++k)
        if (!vanishes(step.coeff(k))) {
          moved = true;
          break;
        }
      step.prec = Series::exact;
      m[i] = (m[i] - step).truncated(cap);
    }
    if (at == cap && !moved && !reference_) break;
    at = std::min(cap, 2 * at);
  }
  SubsMap s = subs;
  std::vector<Series> g(n);
  residual(s, g, nullptr, cap);
  for (int i = 0; i < n; ++i)
    for (int k = g[i].valuation(); k < std::min(g[i].prec, cap - 1); ++k)
      if (!vanishes(g[i].coeff(k)))
        throw NumericalError(
            "the interior node(s) of the discrete Lagrangian could not be eliminated "
            "(∂L_d/∂qm = 0 has no series solution)");
  return m;
}

// V Definition 8: L_mod,K = T_K(L_mesh with x^{(ℓ)}, ℓ ≥ 2, replaced along the modified
// equation).
const std::vector<ex>& Engine::l_mod() {
  if (!lmod_.empty()) return lmod_;
  const auto& m = l_mesh();
  const auto& f = modified_equation();
  const int n = static_cast<int>(solved().size());
  // The modified equation truncated after h^{K−1} (a polynomial in h): what it leaves out
  // enters L_mesh at h^{K+1} at the earliest.
  const int terms = std::max(K_, 1);
  std::vector<Series> F(n);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < terms; ++k) F[i].c.push_back(f[k][i]);
  std::vector<std::vector<ex>> uses;
  for (const ex& e : m) uses.push_back({e});
  const auto jets = jets_along(F, uses, K_ + 1);
  progress::set_stage("L_mod to h^" + std::to_string(K_) + ": L_mesh along the modified equation");
  const Series L = along(m, jets, K_ + 1);
  for (int k = 0; k <= K_; ++k) lmod_.push_back(GiNaC::expand(L.coeff(k)));
  return lmod_;
}

// The first-order modified system from H_mod: ẋ = ∂H/∂p, ṗ = −∂H/∂x (through the potential's
// derivative symbols by JetSpace::partial).
std::pair<std::vector<std::vector<ex>>, std::vector<std::vector<ex>>> Engine::vector_field() {
  const std::vector<ex> H = h_mod();
  const JetSpace& J = *dl_.jets;
  const int n = J.dofs();
  progress::set_stage("vector field to h^" + std::to_string(K_) + ": derivatives of H_mod");
  std::vector<std::vector<ex>> xdot(H.size(), std::vector<ex>(n)), pdot = xdot;
  for (std::size_t k = 0; k < H.size(); ++k)
    for (int i = 0; i < n; ++i) {
      xdot[k][i] = GiNaC::expand(H[k].diff(J.p(i)));
      pdot[k][i] = GiNaC::expand(-J.partial(H[k], 0, i));
    }
  return {xdot, pdot};
}

// Series Legendre transform: p = ∂L/∂ẋ solved for ẋ order by order, H = p·ẋ − L.
std::vector<ex> Engine::h_mod() {
  if (solved().size() != static_cast<std::size_t>(dl_.jets->dofs()))
    throw ArgumentError("--what", "the modified Hamiltonian needs every degree of freedom solved");
  const auto& L = l_mod();
  progress::set_stage("H_mod to h^" + std::to_string(K_) + ": Legendre transform");
  const JetSpace& J = *dl_.jets;
  const int n = J.dofs();
  std::vector<std::vector<ex>> P(L.size(), std::vector<ex>(n));
  for (std::size_t k = 0; k < L.size(); ++k)
    for (int j = 0; j < n; ++j) P[k][j] = GiNaC::expand(L[k].diff(J.x(1, j)));
  GiNaC::matrix M(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      M(i, j) = GiNaC::expand(P[0][i].diff(J.x(1, j)));
      for (int l = 0; l < n; ++l)
        if (!vanishes(M(i, j).diff(J.x(1, l))))
          throw NumericalError(
              "series Legendre transform needs a kinetic energy quadratic in ẋ at order h^0");
    }
  const GiNaC::matrix Minv = inverse_checked(M, "∂²L/∂ẋ²");
  GiNaC::exmap zero;
  for (int j = 0; j < n; ++j) zero[J.x(1, j)] = 0;
  std::vector<Series> V(n);
  for (int i = 0; i < n; ++i) {
    ex acc = 0;
    for (int j = 0; j < n; ++j) acc += Minv(i, j) * (J.p(j) - P[0][j].subs(zero));
    V[i] = Series::constant(GiNaC::expand(acc));  // truncated ansatz, a polynomial in h
  }
  auto vsubs = [&] {
    SubsMap s;
    for (int j = 0; j < n; ++j) s[J.x(1, j)] = V[j];
    return s;
  };
  for (int m = 1; m <= K_; ++m) {
    const SubsMap s = vsubs();
    std::vector<ex> r(n);
    for (int i = 0; i < n; ++i) {
      std::vector<ex> col;
      for (int k = 0; k <= m; ++k) col.push_back(P[k][i]);
      r[i] = shifted_sum(J, col, s, m + 1).coeff(m);
    }
    for (int i = 0; i < n; ++i) {
      ex acc = 0;
      for (int j = 0; j < n; ++j) acc -= Minv(i, j) * r[j];
      V[i].c.push_back(GiNaC::expand(acc));
    }
  }
  const SubsMap s = vsubs();
  Series H = Series::constant(0);
  for (int j = 0; j < n; ++j) H = H + Series::constant(J.p(j)) * V[j];
  H = (H - shifted_sum(J, L, s, K_ + 1)).truncated(K_ + 1);
  std::vector<ex> out;
  for (int k = 0; k <= K_; ++k) out.push_back(GiNaC::expand(H.coeff(k)));
  return out;
}

// Shen & Sun, Theorem 10 and (4.5)–(4.7): Nyström methods.
std::vector<std::vector<ex>> nystrom_modified_equation(std::shared_ptr<JetSpace> J,
                                                       const NystromTableau& tab, int K,
                                                       bool printed_46) {
  if (J->dofs() != 1) throw ArgumentError("--dim", "Nyström methods: one degree of freedom");
  const int s = static_cast<int>(tab.c.size());
  int fam = -1;
  for (int f = 0; f < J->families(); ++f)
    if (J->family_name(f) == "f") fam = f;
  if (fam < 0) fam = J->add_family("f", "f");
  const GiNaC::symbol y("y");
  const ex fy = abstract_call(fam, {y});
  const int P = K + 5, cap = K + 4;
  auto force = [&](const Series& X) { return SeriesEvaluator(*J, {{y, X}}, cap)(fy); };
  const Series h2 = Series::h() * Series::h();
  // Stages of the step that starts at x(t0) and ends at x(t0 + h), s0 = position of t0.
  auto stages = [&](const Series& x0, const Series& x1) {
    std::vector<Series> X(s);
    for (int i = 0; i < s; ++i)
      X[i] = (Series::constant(tab.c[i]) * x1 + Series::constant(1 - tab.c[i]) * x0).truncated(cap);
    for (int it = 0; it < K / 2 + 3; ++it) {
      std::vector<Series> F(s);
      for (int j = 0; j < s; ++j) F[j] = force(X[j]);
      for (int i = 0; i < s; ++i) {
        Series acc = Series::constant(tab.c[i]) * x1 + Series::constant(1 - tab.c[i]) * x0;
        for (int j = 0; j < s; ++j)
          acc = acc + Series::constant(tab.abar[i][j] - tab.c[i] * tab.bbar[j]) * h2 * F[j];
        X[i] = acc.truncated(cap);
      }
    }
    return X;
  };
  const Series xm = shifted_jet(*J, 0, -1, P), x0 = shifted_jet(*J, 0, 0, P),
               xp = shifted_jet(*J, 0, 1, P);
  const auto Sback = stages(xm, x0), Snow = stages(x0, xp);
  Series rhs = Series::constant(0);
  for (int i = 0; i < s; ++i) {
    const ex wb = printed_46 ? tab.bhat[i] : tab.bhat[i] - tab.bbar[i];
    const ex wn = printed_46 ? tab.bbar[i] - tab.bhat[i] : tab.bbar[i];
    rhs = rhs + Series::constant(wb) * force(Sback[i]) + Series::constant(wn) * force(Snow[i]);
  }
  const Series psi = ((xp - Series::constant(2) * x0 + xm) / h2 - rhs).truncated(K + 1);
  if (psi.prec < K + 1) throw std::logic_error("Nyström expansion lost precision");
  std::vector<std::vector<ex>> E(K + 1, std::vector<ex>(1));
  for (int k = 0; k <= K; ++k) E[k][0] = GiNaC::expand(psi.coeff(k));
  SymbolicDL none;
  none.jets = J;
  none.description = "Nyström method";
  const Engine solver(none, K);
  return solver.solve_for_acceleration(E, K);
}

ex radial_form(const ex& e, const GiNaC::symbol& x1, const GiNaC::symbol& x2,
               const GiNaC::symbol& r) {
  const ex rr =
      e.subs(GiNaC::pow(x1 * x1 + x2 * x2, GiNaC::wild(0)) == GiNaC::pow(r, 2 * GiNaC::wild(0)),
             GiNaC::subs_options::algebraic);
  struct Map : GiNaC::map_function {
    const GiNaC::symbol &x1, &x2, &r;
    Map(const GiNaC::symbol& a, const GiNaC::symbol& b, const GiNaC::symbol& c)
        : x1(a), x2(b), r(c) {}
    ex operator()(const ex& x) override {
      if (GiNaC::is_a<GiNaC::power>(x) && x.op(0).is_equal(x2) && GiNaC::is_a<numeric>(x.op(1)) &&
          GiNaC::ex_to<numeric>(x.op(1)).is_pos_integer()) {
        const long n = GiNaC::ex_to<numeric>(x.op(1)).to_long();
        return GiNaC::pow(x2, n % 2) * GiNaC::pow(r * r - x1 * x1, n / 2);
      }
      return x.map(*this);
    }
  } map(x1, x2, r);
  return GiNaC::collect_common_factors(GiNaC::expand(map(GiNaC::expand(rr))));
}

// ---------------------------------------------------------------------------------------------
// Output
// ---------------------------------------------------------------------------------------------

std::string format_series(const std::vector<ex>& c, const GiNaC::symbol& h, Format f) {
  std::ostringstream os;
  const int K = static_cast<int>(c.size()) - 1;
  bool first = true;
  for (int k = 0; k <= K; ++k) {
    if (c[k].is_zero()) continue;
    switch (f) {
      case Format::text:
        os << "h^" << k << ": " << canonical_string(c[k], Format::text) << "\n";
        break;
      case Format::latex:
        if (!first) os << " + ";
        // \Bigl( \Bigr) rather than \left( \right): MathJax breaks a long coefficient over
        // lines only between delimiters of fixed size.
        if (k > 0) os << (k == 1 ? std::string("h") : "h^{" + std::to_string(k) + "}");
        os << "\\Bigl(" << canonical_string(c[k], Format::latex) << "\\Bigr)";
        break;
      case Format::python:
        if (!first) os << " + ";
        if (k == 0)
          os << "(" << canonical_string(c[k], Format::python) << ")";
        else
          os << h.get_name() << "**" << k << "*(" << canonical_string(c[k], Format::python) << ")";
        break;
    }
    first = false;
  }
  if (first) os << (f == Format::text ? "0\n" : "0");
  switch (f) {
    case Format::text:
      os << "+ O(h^" << K + 1 << ")\n";
      break;
    case Format::latex:
      os << " + \\mathcal{O}(h^{" << K + 1 << "})";
      break;
    case Format::python:
      os << "  # + O(" << h.get_name() << "**" << K + 1 << ")";
      break;
  }
  return os.str();
}

}  // namespace vibook::modified
