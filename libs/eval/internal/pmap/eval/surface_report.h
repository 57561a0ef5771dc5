// The surface evaluation as eval.json keys and as a short text report.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "pmap/eval/surface_evaluation.h"

namespace pmap::eval {

/// Adds the surface keys (doc/evaluation.md) to the top level of `doc`.
void addSurfaceKeys(const SurfaceEvaluation& e, const SurfaceEvalOptions& options,
                    nlohmann::json& doc);

/// A few lines for stdout (matched/gt, errors, label scores, clutter
/// rejection) from the keys of `doc`; empty if it has no surface keys.
std::string surfaceReportText(const nlohmann::json& doc);

}  // namespace pmap::eval
