/// \file provenance.hpp
/// \brief What a ledger was measured with: the source commit, the compiler, the libraries
/// vibook was compiled against and runs with, and gnuplot (the book's landing page and the
/// "provenance" object of `claims.json`).
///
/// Chapter: \ref index (section "What we found").
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace vibook::claims {

/// The provenance of a run: `commit` as given (the book build passes git's: the hash, the
/// commit's date and whether the tree had local changes; "" when unknown), vibook's version,
/// the compiler, Eigen, Boost, GiNaC, libqd, MPFR, GMP, fmt and nlohmann-json (the versions
/// compiled against; GiNaC, MPFR and GMP also as loaded now), and gnuplot's version as
/// `gnuplot --version` prints it ("not found" without it). Nothing in it depends on the time
/// of the run, so two runs on one machine and commit give the same bytes.
nlohmann::json provenance(const std::string& commit);

/// One HTML paragraph for the landing page: the commit and the versions, and whether this
/// build measured every claim (`pending` claims: the long studies were not run).
std::string provenance_html(const nlohmann::json& provenance, int pending);

}  // namespace vibook::claims
