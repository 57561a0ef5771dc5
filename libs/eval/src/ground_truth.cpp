#include "pmap/eval/ground_truth.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>

#include "pmap/common/error.h"
#include "pmap/eval/map_files.h"

namespace pmap::eval {
namespace {

using nlohmann::json;

class Fields {
 public:
  explicit Fields(std::string file) : file_(std::move(file)) {}
  const json& at(const json& j, const std::string& key, const std::string& where) const {
    if (!j.is_object() || !j.contains(key)) {
      fail(where + "." + key + " is missing");
    }
    return j.at(key);
  }
  double number(const json& j, const std::string& key, const std::string& where) const {
    return finite(at(j, key, where), where + "." + key);
  }
  /// A finite number (the parser already refuses nan, inf and overflow).
  double finite(const json& v, const std::string& where) const {
    if (!v.is_number()) {
      fail(where + " is not a number");
    }
    const double d = v.get<double>();
    if (!std::isfinite(d)) {
      fail(where + " is not finite");
    }
    return d;
  }
  /// An integer in int range (ids, indices).
  int integer(const json& v, const std::string& where) const {
    const double d = finite(v, where);
    if (d != std::floor(d) || d < std::numeric_limits<int>::min() ||
        d > std::numeric_limits<int>::max()) {
      fail(where + " is not an integer in int range");
    }
    return static_cast<int>(d);
  }
  int integer(const json& j, const std::string& key, const std::string& where) const {
    return integer(at(j, key, where), where + "." + key);
  }
  Eigen::Vector3d vec3(const json& v, const std::string& where) const {
    if (!v.is_array() || v.size() != 3) {
      fail(where + " is not an [x, y, z] array");
    }
    return {finite(v[0], where + "[0]"), finite(v[1], where + "[1]"), finite(v[2], where + "[2]")};
  }
  Eigen::Vector2d vec2(const json& v, const std::string& where) const {
    if (!v.is_array() || v.size() < 2) {
      fail(where + " is not an [x, y] array");
    }
    return {finite(v[0], where + "[0]"), finite(v[1], where + "[1]")};
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(file_ + ": ground truth: " + what);
  }

 private:
  std::string file_;
};

/// nlohmann's DOM builder, remembering where the parser failed (its
/// exceptions for a number overflow, "1e999", carry no position).
class LocatingDomParser : public nlohmann::detail::json_sax_dom_parser<json> {
 public:
  explicit LocatingDomParser(json& result) : json_sax_dom_parser(result, false) {}
  template <class Exception>
  bool parse_error(std::size_t position, const std::string& token, const Exception& ex) {
    position_ = position;
    message_ = ex.what();
    return json_sax_dom_parser::parse_error(position, token, ex);
  }
  std::size_t position() const { return position_; }
  const std::string& message() const { return message_; }

 private:
  std::size_t position_ = 0;
  std::string message_;
};

json parseFile(const std::filesystem::path& path) {
  requireRegularFile(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw InputError(path.string() + ": cannot open ground truth file");
  }
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  json doc;
  LocatingDomParser parser(doc);
  if (!json::sax_parse(text, &parser)) {
    const std::size_t end = std::min(parser.position(), text.size());
    const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(end), '\n');
    throw InputError(path.string() + ":" + std::to_string(line) +
                     ": not valid JSON: " + parser.message());
  }
  return doc;
}

void readPoses(const json& doc, const Fields& f, GroundTruth& gt) {
  const json& poses = f.at(doc, "poses", "");
  for (size_t i = 0; i < poses.size(); ++i) {
    const json& p = poses[i];
    if (!p.is_array() || p.size() != 7) {
      f.fail("poses[" + std::to_string(i) + "] is not [t, x, y, z, yaw, pitch, roll]");
    }
    double v[7];
    for (std::size_t k = 0; k < 7; ++k) {
      v[k] = f.finite(p[k], "poses[" + std::to_string(i) + "][" + std::to_string(k) + "]");
    }
    gt.poses.append(v[0], mrpt::math::TPose3D(v[1], v[2], v[3], v[4], v[5], v[6]));
  }
}

void readSurfaces(const json& doc, const Fields& f, GroundTruth& gt) {
  for (const json& s : f.at(doc, "surfaces", "")) {
    GtRectangle r;
    r.id = f.integer(s, "id", "surfaces[]");
    const std::string where = "surfaces[id " + std::to_string(r.id) + "]";
    r.kind = f.at(s, "kind", where).get<std::string>();
    const json& c = f.at(s, "corners", where);
    if (!c.is_array() || c.size() != 4) {
      f.fail(where + ".corners must have 4 points");
    }
    for (int k = 0; k < 4; ++k) {
      r.corners[k] = f.vec3(c[k], where + ".corners");
    }
    r.normal = f.vec3(f.at(s, "normal", where), where + ".normal");
    if (s.contains("parent") && s["parent"].is_number()) {
      r.parent = f.integer(s["parent"], where + ".parent");
    }
    gt.surfaces.push_back(r);
  }
}

void readPosters(const json& doc, const Fields& f, const std::filesystem::path& dir,
                 GroundTruth& gt) {
  if (!doc.contains("posters")) {
    return;
  }
  for (const json& p : doc["posters"]) {
    GtPoster poster;
    poster.id = f.integer(p, "id", "posters[]");
    const std::string where = "posters[id " + std::to_string(poster.id) + "]";
    poster.wall_id = f.integer(p, "wall_id", where);
    const json& c = f.at(p, "corners", where);
    if (!c.is_array() || c.size() != 4) {
      f.fail(where + ".corners must have 4 points");
    }
    for (int k = 0; k < 4; ++k) {
      poster.corners[k] = f.vec3(c[k], where + ".corners");
    }
    poster.image = dir / f.at(p, "image", where).get<std::string>();
    poster.pixels_per_m = f.number(p, "pixels_per_m", where);
    gt.posters.push_back(poster);
  }
}

void readClutter(const json& doc, const Fields& f, GroundTruth& gt) {
  if (!doc.contains("clutter")) {
    return;
  }
  for (const json& c : doc["clutter"]) {
    const int id = f.integer(c, "id", "clutter[]");
    const std::string where = "clutter[id " + std::to_string(id) + "]";
    const std::string shape = f.at(c, "shape", where).get<std::string>();
    const std::string kind = f.at(c, "kind", where).get<std::string>();
    if (shape == "cylinder") {
      GtCylinder y{id, kind, {}, 0, 0, 0};
      y.centre = f.vec2(f.at(c, "centre", where), where + ".centre");
      y.radius = f.number(c, "radius_m", where);
      y.z_min = f.number(c, "z_min_m", where);
      y.z_max = f.number(c, "z_max_m", where);
      gt.cylinders.push_back(y);
    } else if (shape == "box") {
      GtBox b;
      b.id = id;
      b.kind = kind;
      const Eigen::Vector2d centre = f.vec2(f.at(c, "centre", where), where + ".centre");
      const Eigen::Vector3d size = f.vec3(f.at(c, "size_m", where), where + ".size_m");
      b.centre = centre;
      b.yaw = c.contains("yaw") ? f.finite(c["yaw"], where + ".yaw") : 0.0;
      b.min = Eigen::Vector3d(-size.x() / 2, -size.y() / 2, f.number(c, "z_min_m", where));
      b.max = Eigen::Vector3d(size.x() / 2, size.y() / 2, f.number(c, "z_max_m", where));
      gt.boxes.push_back(b);
    } else {
      f.fail(where + ".shape '" + shape + "' is not cylinder or box");
    }
  }
}

void readPeople(const json& doc, const Fields& f, GroundTruth& gt) {
  if (!doc.contains("people")) {
    return;
  }
  for (const json& p : doc["people"]) {
    gt.people.push_back(f.integer(p, "id", "people[]"));
  }
}

/// Fast path for the many hit ids: a JSON integer in int range.
bool intValue(const json& v, int& out) {
  if (v.is_number_unsigned()) {
    const auto u = v.get<std::uint64_t>();
    out = static_cast<int>(u);
    return u <= static_cast<std::uint64_t>(std::numeric_limits<int>::max());
  }
  if (v.is_number_integer()) {
    const auto i = v.get<std::int64_t>();
    out = static_cast<int>(i);
    return i >= std::numeric_limits<int>::min() && i <= std::numeric_limits<int>::max();
  }
  return false;
}

void readHits(const json& doc, const Fields& f, GroundTruth& gt) {
  for (const json& s : f.at(doc, "structure_scans", "")) {
    const int index = f.integer(s, "index", "structure_scans[]");
    const std::string where = "structure_scans[index " + std::to_string(index) + "]";
    const json& hits = f.at(s, "hits", where);
    if (!hits.is_array()) {
      f.fail(where + ".hits is not an array");
    }
    std::vector<int>& ids = gt.hits[index];
    ids.clear();
    ids.reserve(hits.size());
    for (std::size_t k = 0; k < hits.size(); ++k) {
      int id = 0;
      if (!intValue(hits[k], id)) {  // the slow path builds the message
        id = f.integer(hits[k], where + ".hits[" + std::to_string(k) + "]");
      }
      ids.push_back(id);
    }
  }
}

}  // namespace

double distanceToCylinder(const GtCylinder& c, const Eigen::Vector3d& p) {
  const double dr = (p.head<2>() - c.centre).norm() - c.radius;  // > 0: outside the side
  const double dz = std::max(c.z_min - p.z(), p.z() - c.z_max);  // > 0: below or above
  if (dz <= 0) {
    return dr > 0 ? dr : std::min(-dr, -dz);  // inside: nearest of side and caps
  }
  return dr > 0 ? std::hypot(dr, dz) : dz;
}

double distanceToBox(const GtBox& b, const Eigen::Vector3d& p) {
  const Eigen::Vector3d q = b.local(p);
  const Eigen::Vector3d outside = (b.min - q).cwiseMax(q - b.max).cwiseMax(0.0);
  if (outside.squaredNorm() > 0) {
    return outside.norm();
  }
  return (q - b.min).cwiseMin(b.max - q).minCoeff();  // inside: distance to the nearest face
}

double distanceToRectangle(const std::array<Eigen::Vector3d, 4>& c, const Eigen::Vector3d& p) {
  const Eigen::Vector3d u = c[1] - c[0];
  const Eigen::Vector3d v = c[3] - c[0];
  const double lu = u.norm();
  const double lv = v.norm();
  if (lu == 0 || lv == 0) {
    return (p - c[0]).norm();
  }
  const Eigen::Vector3d eu = u / lu;
  const Eigen::Vector3d ev = (v - eu * eu.dot(v)).normalized();
  const Eigen::Vector3d n = eu.cross(ev);
  const Eigen::Vector3d d = p - c[0];
  const double a = std::clamp(d.dot(eu), 0.0, lu);
  const double b = std::clamp(d.dot(ev), 0.0, ev.dot(v));
  const double h = d.dot(n);
  const Eigen::Vector3d in_plane = d - n * h;
  const double da = d.dot(eu) - a;
  const double db = in_plane.dot(ev) - b;
  return std::sqrt(h * h + da * da + db * db);
}

Eigen::Vector3d GtBox::local(const Eigen::Vector3d& p) const {
  const double c = std::cos(-yaw);
  const double s = std::sin(-yaw);
  const Eigen::Vector2d d = p.head<2>() - centre;
  return {c * d.x() - s * d.y(), s * d.x() + c * d.y(), p.z()};
}

const GtRectangle* GroundTruth::surface(int id) const {
  for (const auto& s : surfaces) {
    if (s.id == id) {
      return &s;
    }
  }
  return nullptr;
}

bool GroundTruth::isClutter(int id) const {
  for (const auto& c : cylinders) {
    if (c.id == id)
      return true;
  }
  for (const auto& b : boxes) {
    if (b.id == id)
      return true;
  }
  return false;
}

bool GroundTruth::isPerson(int id) const {
  return std::find(people.begin(), people.end(), id) != people.end();
}

double GroundTruth::distance(int id, const Eigen::Vector3d& p) const {
  if (const GtRectangle* r = surface(id)) {
    return distanceToRectangle(r->corners, p);
  }
  for (const auto& c : cylinders) {
    if (c.id == id)
      return distanceToCylinder(c, p);
  }
  for (const auto& b : boxes) {
    if (b.id == id)
      return distanceToBox(b, p);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

GroundTruth readGroundTruth(const std::filesystem::path& path) {
  const json doc = parseFile(path);
  const Fields f(path.string());
  GroundTruth gt;
  try {
    gt.world = f.at(doc, "world", "").get<std::string>();
    gt.sigma_m = f.number(doc, "sigma_m", "");
    readPoses(doc, f, gt);
    readSurfaces(doc, f, gt);
    readClutter(doc, f, gt);
    readPeople(doc, f, gt);
    readPosters(doc, f, path.parent_path(), gt);

    readHits(doc, f, gt);
  } catch (const json::exception& e) {
    f.fail(std::string("unexpected field type: ") + e.what());
  }
  if (gt.poses.empty()) {
    f.fail("no poses");
  }
  return gt;
}

}  // namespace pmap::eval
