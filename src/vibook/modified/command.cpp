// `vibook modified` as a library call (command.hpp): the engine's derivation for one method
// and system, printed as text, LaTeX or a SymPy script.
#include "vibook/modified/command.hpp"

#include <memory>
#include <mutex>
#include <set>

#include <fmt/format.h>

#include "vibook/mechanics/discrete_lagrangian.hpp"
#include "vibook/modified/vector_notation.hpp"

namespace vibook::modified {

namespace {

// Every symbol in the expressions, for the Python header (sorted by name, h first).
void collect_symbols(const GiNaC::ex& e, std::set<std::string>& out) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    out.insert(GiNaC::ex_to<GiNaC::symbol>(e).get_name());
    return;
  }
  for (std::size_t k = 0; k < e.nops(); ++k) collect_symbols(e.op(k), out);
}

// The discrete Lagrangian of method m on the user's continuous Lagrangian L(q, v) (typed, in
// `vibook verify`'s language), through the same templates as the library's methods
// (mechanics/discrete_lagrangian.hpp, Vermeeren 2017 Example 1).
template <int N>
modified::SymbolicDL typed_method_dl(modified::Method m,
                                     const verify::TypedDiscreteLagrangian& typed,
                                     std::shared_ptr<modified::JetSpace> jets,
                                     const std::string& what) {
  const auto L = [&typed](const auto& q, const auto& v) -> scalar_t<decltype(q)> {
    using S = scalar_t<decltype(q)>;
    return typed.lagrangian<N, S>(Vec<S, N>(q), Vec<S, N>(v));
  };
  switch (m) {
    case modified::Method::sv:
      return modified::symbolic_dl<N>(stormer_verlet_dl(L), std::move(jets), what);
    case modified::Method::midpoint:
      return modified::symbolic_dl<N>(midpoint_dl(L), std::move(jets), what);
    case modified::Method::se:
      return modified::symbolic_dl<N>(symplectic_euler_dl(L), std::move(jets), what);
    default:
      return modified::symbolic_dl<N>(symplectic_euler_adjoint_dl(L), std::move(jets), what);
  }
}

}  // namespace

std::string derive(const Derivation& d) {
  const Method m = d.method;
  const Potential p = d.potential;
  const Format f = d.format;
  const int dim = d.dim;
  std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  std::string out;
  const auto user_dl = [&]() -> SymbolicDL {
    auto jets = std::make_shared<JetSpace>(dim);
    if (d.typed_lagrangian) {
      const std::string& what = d.description;
      switch (dim) {
        case 1:
          return typed_method_dl<1>(m, *d.typed, jets, what);
        case 2:
          return typed_method_dl<2>(m, *d.typed, jets, what);
        default:
          return typed_method_dl<3>(m, *d.typed, jets, what);
      }
    }
    const std::string& what = d.description;
    switch (dim) {
      case 1:
        return symbolic_dl<1>(d.typed->bind<1>(), jets, what);
      case 2:
        return symbolic_dl<2>(d.typed->bind<2>(), jets, what);
      default:
        return symbolic_dl<3>(d.typed->bind<3>(), jets, what);
    }
  };
  Engine E(d.typed ? user_dl() : make_discrete_lagrangian(m, p, dim, d.alpha), d.order);
  E.use_reference_path(d.reference);
  const JetSpace& J = E.jets();
  const std::string comment = f == Format::latex ? "%" : "#";
  // Derive first, print after: the Python header lists every symbol that occurs.
  std::vector<std::pair<std::string, std::vector<ex>>> blocks;  // (left-hand side, series)
  // The vector quantities whole, for the vector notation: (left-hand side, field[k][i]).
  std::vector<std::pair<std::string, std::vector<std::vector<ex>>>> vector_blocks;
  std::string cross;
  auto lhs_of = [&](const char* latex, const char* python, const char* text) {
    return std::string(f == Format::latex ? latex : (f == Format::python ? python : text));
  };
  // One block per component of a vector series field[k][i]: lhs, lhs_1, … (lhs1, … in text).
  const auto add_components = [&](const std::string& lhs,
                                  const std::vector<std::vector<ex>>& field) {
    vector_blocks.emplace_back(lhs, field);
    for (int i = 0; i < J.dofs(); ++i) {
      std::vector<ex> c;
      for (const auto& row : field) c.push_back(row[i]);
      const std::string name = J.dofs() == 1        ? lhs
                               : f == Format::latex ? fmt::format("{}_{{{}}}", lhs, i + 1)
                                                    : fmt::format("{}{}", lhs, i + 1);
      blocks.emplace_back(name, c);
    }
  };
  if (d.what == "equation") {
    const auto fm = E.modified_equation();
    if (d.cross_check) {
      const auto fd = E.modified_equation_direct();
      for (std::size_t k = 0; k < fm.size(); ++k)
        for (int i = 0; i < J.dofs(); ++i)
          if (!vanishes(fm[k][i] - fd[k][i]))
            throw NumericalError(fmt::format(
                "the meshed and the direct route disagree at h^{} (component {})", k, i + 1));
      cross = "cross-check: the direct route (Vermeeren §3.2) agrees term by term";
    }
    add_components(lhs_of("\\ddot{x}", "a", "xddot"), fm);
  } else if (d.what == "lagrangian") {
    blocks.emplace_back(lhs_of("L_{\\mathrm{mod}}", "L", "L_mod"), E.l_mod());
  } else if (d.what == "hamiltonian") {
    blocks.emplace_back(lhs_of("H_{\\mathrm{mod}}", "H", "H_mod"), E.h_mod());
  } else if (d.what == "vector-field") {
    const auto [xdot, pdot] = E.vector_field();
    add_components(lhs_of("\\dot{x}", "xdot", "xdot"), xdot);
    add_components(lhs_of("\\dot{p}", "pdot", "pdot"), pdot);
  } else if (d.what == "meshed") {
    blocks.emplace_back(lhs_of("L_{\\mathrm{mesh}}", "L_mesh", "L_mesh"), E.l_mesh());
  } else if (d.what == "disc") {
    blocks.emplace_back(lhs_of("L_{\\mathrm{disc}}", "L_disc", "L_disc"), E.l_disc());
  } else {
    throw ArgumentError("--what", fmt::format("unknown '{}' (equation, lagrangian, hamiltonian, "
                                              "vector-field, meshed, disc)",
                                              d.what));
  }
  // Kepler: display in r = |x| (radial_form), a canonical and much shorter form.
  const bool radial = !d.typed && p == Potential::kepler;
  const GiNaC::symbol r("r", "|x|");
  if (radial)
    for (auto& [lhs, c] : blocks)
      for (ex& e : c) e = radial_form(e, J.x(0, 0), J.x(0, 1), r);
  out += fmt::format("{} {}; order h^{}\n", comment, E.discrete_lagrangian().description, d.order);
  if (radial && f != Format::python)
    out += fmt::format("{} r = |x| = sqrt(x1^2 + x2^2)\n", comment);
  if (!cross.empty()) out += fmt::format("{} {}\n", comment, cross);
  if (f == Format::python) {
    std::set<std::string> names;
    for (const auto& [lhs, c] : blocks)
      for (const ex& e : c) collect_symbols(e, names);
    names.erase("h");
    names.erase("r");
    std::string list = "h";
    for (const auto& n : names) list += " " + n;
    std::string lhs_list = list;
    for (auto& ch : lhs_list)
      if (ch == ' ') ch = ',';
    out += fmt::format("from sympy import Rational, symbols, sqrt, cos, sin\n");
    out += fmt::format("{} = symbols('{}')\n", lhs_list, list);
    if (radial) out += fmt::format("r = sqrt(x1**2 + x2**2)\n");
  }
  // LaTeX of an abstract potential in 2-3 dimensions: in vector notation, as Shen & Sun write
  // theirs (vector_notation.hpp), unless --components.
  if (f == Format::latex && !d.components && !radial) {
    std::vector<ex> all;
    for (const auto& [lhs, c] : blocks) all.insert(all.end(), c.begin(), c.end());
    if (const auto vn = VectorNotation::of(J, all)) {
      if (!vector_blocks.empty()) {
        for (const auto& [lhs, field] : vector_blocks)
          out += fmt::format("{} = {}\n", lhs, vn->vector_series(field));
      } else {
        for (const auto& [lhs, c] : blocks)
          out += fmt::format("{} = {}\n", lhs, vn->scalar_series(c));
      }
      return out;
    }
  }
  for (const auto& [lhs, c] : blocks) {
    if (f == Format::text)
      out += fmt::format("# {} =\n", lhs);
    else
      out += fmt::format("{} = ", lhs);
    out += fmt::format("{}\n", format_series(c, J.h(), f));
  }
  return out;
}

}  // namespace vibook::modified
