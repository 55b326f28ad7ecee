// Helpers of the printed-formula checks (printed_checks.hpp).
#include <algorithm>
#include <utility>

#include "vibook/modified/printed_checks.hpp"

namespace vibook::checks::printed_detail {

claims::ClaimResult claim(const std::string& id, const std::string& note) {
  claims::ClaimResult r;
  r.id = id;
  r.source = kCheck;
  r.status = claims::Status::reproduced;
  r.note = note;
  return r;
}

void add_evidence(std::vector<claims::ClaimResult>& errata, const std::string& id,
                  const std::string& text) {
  for (auto& e : errata)
    if (e.id == id) e.note += text;
}

std::vector<ex> shifted_taylor(const modified::JetSpace& J, int dof, const GiNaC::numeric& step,
                               int K) {
  std::vector<ex> c;
  GiNaC::numeric fact = 1;
  for (int k = 0; k <= K; ++k) {
    if (k > 0) fact *= k;
    c.push_back(GiNaC::pow(step, k) / fact * J.x(k, dof));
  }
  return c;
}

ex series_sum(const std::vector<ex>& c, const GiNaC::symbol& h, int through) {
  ex s = 0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    if (through >= 0 && static_cast<int>(k) > through) break;
    s += c[k] * GiNaC::pow(h, static_cast<int>(k));
  }
  return s;
}

void Compared::operator()(Paper p, const std::string& quote, const std::string& part,
                          const std::string& against, const JetNotation& n, const Target& t,
                          std::vector<std::size_t> members, bool equation,
                          const std::string& role) {
  Spec s;
  s.paper = p;
  s.quote = quote;
  s.part = part;
  s.against = against;
  s.members = std::move(members);
  s.equation = equation;
  s.role = role;
  spec(std::move(s), {{&n, t, ""}});
}

void Compared::spec(Spec s, const std::vector<Case>& cases) {
  s.check = check;
  list.push_back(printed::compare(s, cases));
}

std::vector<claims::FormulaComparison> Compared::take() {
  std::vector<claims::FormulaComparison> out;
  std::swap(out, list);
  return out;
}

std::function<ex(const ex&)> on_shell(const modified::JetSpace& J, std::vector<int> dofs,
                                      const std::vector<std::vector<ex>>& f, int K) {
  const GiNaC::symbol h = J.h();
  std::vector<ex> F;
  for (int d : dofs) {
    ex Fd = 0;
    for (int k = 0; k <= K && k < static_cast<int>(f.size()); ++k)
      Fd += f[static_cast<std::size_t>(k)][static_cast<std::size_t>(d)] * GiNaC::pow(h, k);
    F.push_back(Fd);
  }
  return [&J, dofs, F, h, K](const ex& e) {
    auto second = [&](const ex& x) {  // replace ẍ by F
      GiNaC::exmap m;
      for (std::size_t i = 0; i < dofs.size(); ++i) m[J.x(2, dofs[i])] = F[i];
      return x.subs(m);
    };
    ex out = e;
    for (int pass = 0; pass < 4; ++pass) {
      int top = -1;
      for (int d : dofs) top = std::max(top, J.max_order(out, d));
      if (top < 2) break;
      for (int m = top; m >= 2; --m) {
        GiNaC::exmap sub;
        for (std::size_t i = 0; i < dofs.size(); ++i) {
          ex Fm = F[i];
          for (int j = 2; j < m; ++j) Fm = second(J.total(Fm));
          sub[J.x(m, dofs[i])] = Fm;
        }
        out = out.subs(sub);
      }
    }
    return GiNaC::series_to_poly(GiNaC::expand(out).series(h == 0, K + 1));
  };
}

JetNotation engine_notation(modified::Engine& E, const std::string& curve) {
  auto J = std::shared_ptr<const modified::JetSpace>(E.discrete_lagrangian().jets);
  JetNotation n(J);
  std::vector<int> dofs;
  for (int i = 0; i < J->dofs(); ++i) dofs.push_back(i);
  n.curve(curve, dofs);
  modified::Engine* engine = &E;
  const GiNaC::symbol h = J->h();
  n.callable("mathcal{L}", [engine, h](const printed::Atom& a, const std::vector<Value>&) -> Value {
    const std::string sub = a.sub_text();
    if (sub.empty()) return Value::scalar(engine->l_disc().at(0));  // the continuous L at the jets
    if (sub == "disc") return Value::scalar(series_sum(engine->l_disc(), h));
    if (sub == "mesh") return Value::scalar(series_sum(engine->l_mesh(), h));
    if (sub.rfind("mod", 0) == 0) {
      int k = -1;
      if (sub.size() > 4 && sub[3] == ',') k = std::stoi(sub.substr(4));
      return Value::scalar(series_sum(engine->l_mod(), h, k));
    }
    throw printed::ReadError("the notation has no \\mathcal{L}_{" + sub + "}");
  });
  return n;
}

}  // namespace vibook::checks::printed_detail
