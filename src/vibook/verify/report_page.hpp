/// \file report_page.hpp
/// \brief The report page of a one-step-map route (`vibook verify --report DIR` with --method,
/// --tableau, --composition or a black box). The page of a typed --ld is ld_study.hpp's
/// write_ld_report; both are written by report_page.cpp with one head and one table style.
#pragma once

#include <filesystem>
#include <string>

#include "vibook/verify/map_study.hpp"

namespace vibook::verify {

/// index.html with the verdicts' table (from the same JSON as --json-out) and the text report,
/// verify.json, the order study's convergence.csv; filled beside `final_dir` and renamed onto
/// it. IoError/ArgumentError on a failed write.
void write_map_report(const MapMeasurement& m, const std::string& command_line,
                      const std::filesystem::path& final_dir);

}  // namespace vibook::verify
