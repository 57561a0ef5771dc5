#include "pmap/eval/surface_report.h"

#include <cstdio>

namespace pmap::eval {
namespace {
using nlohmann::json;

json optionalJson(const std::optional<double>& v) {
  return v ? json(*v) : json(nullptr);
}

json summaryJson(const ErrorSummary& s) {
  return {{"mean", optionalJson(s.mean())}, {"max", s.count > 0 ? json(s.max) : json(nullptr)}};
}

json perSurfaceJson(const std::vector<SurfaceScore>& scores) {
  json list = json::array();
  for (const auto& s : scores) {
    list.push_back({{"gt_id", s.gt_id},
                    {"kind", s.kind},
                    {"hits", s.hits},
                    {"map_id", s.map_id},
                    {"map_surfaces_matching", s.map_surfaces_matching},
                    {"points", s.points},
                    {"normal_error_deg", s.normal_error_deg},
                    {"offset_error_m", s.offset_error_m},
                    {"corner_error_m", s.corner_error_m},
                    {"corner_error_closed_m", s.corner_error_closed_m},
                    {"matching_spread_m", s.matching_spread_m}});
  }
  return list;
}

json perSeamJson(const std::vector<SeamSide>& seams) {
  json list = json::array();
  for (const auto& s : seams) {
    list.push_back({{"gt_id", s.gt_id},
                    {"gt_other", s.gt_other},
                    {"map_id", s.map_id},
                    {"map_other", s.map_other},
                    {"gap_m", s.gap_m}});
  }
  return list;
}

json byKindJson(const std::map<std::string, KindCounts>& kinds) {
  json out = json::object();
  for (const auto& [kind, c] : kinds) {
    out[kind] = {{"gt", c.gt}, {"matched", c.matched}};
  }
  return out;
}

json unmatchedJson(const std::vector<UnmatchedSurface>& unmatched) {
  json list = json::array();
  for (const auto& u : unmatched) {
    list.push_back({{"id", u.id}, {"kind", u.kind}, {"hits", u.hits}});
  }
  return list;
}

/// "%.4f" of a number, "-" for null.
std::string fmt(const json& v, const char* format = "%.4f") {
  if (!v.is_number()) {
    return "-";
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v.get<double>());
  return buf;
}

}  // namespace

void addSurfaceKeys(const SurfaceEvaluation& e, const SurfaceEvalOptions& options, json& doc) {
  const LabelMetrics& l = e.labels;
  doc["surfaces"] = e.surfaces;
  doc["map_surfaces_unmatched"] = e.map_surfaces_unmatched;
  doc["gt_surfaces"] = e.gt_surfaces;
  doc["matched_surfaces"] = e.matched_surfaces;
  doc["matched_by_kind"] = byKindJson(e.matched_by_kind);
  doc["unmatched"] = unmatchedJson(e.unmatched);
  doc["normal_error_deg"] = summaryJson(e.normal_error_deg);
  doc["offset_error_m"] = summaryJson(e.offset_error_m);
  doc["corner_error_m"] = summaryJson(e.corner_error_m);
  doc["corner_error_closed_m"] = summaryJson(e.corner_error_closed_m);
  doc["per_surface"] = perSurfaceJson(e.per_surface);
  doc["seam_gap_m"] = summaryJson(e.seam_gap_m);
  doc["seam_sides"] = e.seams.size();
  doc["per_seam"] = perSeamJson(e.seams);
  doc["label_recall"] = optionalJson(l.recall);
  doc["label_precision"] = optionalJson(l.precision);
  doc["label_f1"] = optionalJson(l.f1);
  doc["label_points"] = {{"on_surface", l.on_surface_points},
                         {"recalled", l.recalled_points},
                         {"assigned", l.assigned_points},
                         {"correct", l.correct_points}};
  doc["clutter_points"] = l.clutter_points;
  doc["clutter_rejected_fraction"] = optionalJson(l.clutter_rejected_fraction);
  json by_truth = json::object();
  for (const auto& [name, t] : l.by_truth) {
    by_truth[name] = {{"points", t.points}, {"on_map_surface", t.on_map_surface}};
  }
  doc["points_by_truth"] = by_truth;
  doc["surface_options"] = {{"min_hits", options.min_hits},
                            {"min_label_share", options.match.min_label_share},
                            {"max_normal_angle_deg", options.match.max_normal_angle_deg}};
}

std::string surfaceReportText(const json& doc) {
  if (!doc.contains("matched_surfaces")) {
    return {};
  }
  char buf[512];
  std::string text;
  std::snprintf(buf, sizeof buf, "surfaces matched %zu / %zu (map surfaces %zu)\n",
                doc["matched_surfaces"].get<std::size_t>(), doc["gt_surfaces"].get<std::size_t>(),
                doc["surfaces"].get<std::size_t>());
  text += buf;
  std::snprintf(
      buf, sizeof buf,
      "surface errors mean/max: normal %s/%s deg, offset %s/%s m, corner %s/%s m\n",
      fmt(doc["normal_error_deg"]["mean"], "%.2f").c_str(),
      fmt(doc["normal_error_deg"]["max"], "%.2f").c_str(),
      fmt(doc["offset_error_m"]["mean"]).c_str(), fmt(doc["offset_error_m"]["max"]).c_str(),
      fmt(doc["corner_error_m"]["mean"]).c_str(), fmt(doc["corner_error_m"]["max"]).c_str());
  text += buf;
  if (doc.contains("seam_gap_m")) {
    std::snprintf(buf, sizeof buf,
                  "seam gaps mean/max: %s/%s m over %zu seam sides; corner (closed reference) "
                  "%s/%s m\n",
                  fmt(doc["seam_gap_m"]["mean"]).c_str(), fmt(doc["seam_gap_m"]["max"]).c_str(),
                  doc["seam_sides"].get<std::size_t>(),
                  fmt(doc["corner_error_closed_m"]["mean"]).c_str(),
                  fmt(doc["corner_error_closed_m"]["max"]).c_str());
    text += buf;
  }
  std::snprintf(buf, sizeof buf, "labels: recall %s, precision %s, F1 %s\n",
                fmt(doc["label_recall"]).c_str(), fmt(doc["label_precision"]).c_str(),
                fmt(doc["label_f1"]).c_str());
  text += buf;
  std::snprintf(buf, sizeof buf, "clutter rejected %s of %zu points\n",
                fmt(doc["clutter_rejected_fraction"]).c_str(),
                doc["clutter_points"].get<std::size_t>());
  text += buf;
  return text;
}

}  // namespace pmap::eval
