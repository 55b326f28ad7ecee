/// \file typed_study_system.hpp
/// \brief The system of a catalogue method measured on a typed potential (method_typed.cpp,
/// tableau_typed.cpp): already set in the study by the caller, so only its report line and
/// JSON. Internal: not installed.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "vibook/verify/map_study.hpp"

namespace vibook::verify {

inline StudySystem typed_study_system(const std::string& line, const std::vector<double>& q0,
                                      const std::vector<double>& p0) {
  // The study's system is the caller's (set from the same expression): nothing to set here.
  return {[](MapStudy&) {}, line,
          nlohmann::json{{"name", "typed"}, {"system", line}, {"q0", q0}, {"p0", p0}}};
}

}  // namespace vibook::verify
