#include "riser_sim/run/range_graph.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "riser_sim/spatial/forces/seabed.h"

namespace riser_sim {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void start(Envelope& e, const std::vector<double>& v) {
  e.min = v;
  e.max = v;
}

void widen(Envelope& e, const double* v, size_t n) {
  for (size_t i = 0; i < n; ++i) {
    e.min[i] = std::min(e.min[i], v[i]);
    e.max[i] = std::max(e.max[i], v[i]);
  }
}

// The arc length of the largest value of `v` at the stations `s` (NaN when empty).
double argMax(const std::vector<double>& v, const std::vector<double>& s) {
  if (v.empty()) return kNaN;
  return s[static_cast<size_t>(std::max_element(v.begin(), v.end()) - v.begin())];
}

}  // namespace

SeabedPlane seabedPlane(const Scene& scene) {
  SeabedPlane p;
  p.exists = scene.seabed.enabled;
  if (!p.exists) return p;
  // The contact force's own plane (gravity along -z in the outputs' frame; a planar scene's y up is z).
  const spatial::Seabed bed(scene.seabed, Vec3(0.0, 0.0, -scene.gravity));
  p.normal = bed.normal();
  p.offset = bed.penetration(Vec3::Zero());  // penetration(x) = offset - n·x
  return p;
}

RangeGraph::RangeGraph(const RunOutputs& first, const SeabedPlane& seabed)
    : seabed_(seabed), td_min_(kNaN), td_max_(kNaN) {
  const size_t nb = first.arc_length.size();
  if (nb < 1 || first.axial_force.size() != nb || first.points.size() != nb + 1 ||
      first.bending_moment.size() + 1 != nb || first.curvature.size() + 1 != nb)
    throw std::invalid_argument("RangeGraph: outputs with " + std::to_string(nb) + " rfes, " +
                                std::to_string(first.axial_force.size()) + " axial forces, " +
                                std::to_string(first.points.size()) + " points and " +
                                std::to_string(first.curvature.size()) + " joints (expected n + 1, n + 2, n)");
  s_ = first.arc_length;
  // Joint A_i starts rfe i: s_begin_0 = 0, s_begin_{i+1} = 2 s_mid_i - s_begin_i; the end is s_begin_{n+1}.
  s_point_.assign(nb + 1, 0.0);
  for (size_t i = 0; i < nb; ++i) {
    s_point_[i + 1] = 2.0 * s_[i] - s_point_[i];
    if (!(s_point_[i + 1] > s_[i] && s_[i] > s_point_[i]))
      throw std::invalid_argument("RangeGraph: the rfes' arc lengths do not increase along the line at rfe " +
                                  std::to_string(i));
  }
  s_joint_.assign(s_point_.begin() + 1, s_point_.end() - 1);
  start(tension_, first.axial_force);
  start(moment_, first.bending_moment);
  start(curvature_, first.curvature);
  if (seabed_.exists) {
    clearance_.min.assign(nb, 0.0);
    clearance_.max.assign(nb, 0.0);
  }
  add(first);
}

void RangeGraph::add(const RunOutputs& o) {
  ++samples_;
  widen(tension_, o.axial_force.data(), tension_.min.size());
  widen(moment_, o.bending_moment.data(), moment_.min.size());
  widen(curvature_, o.curvature.data(), curvature_.min.size());
  if (!seabed_.exists) return;
  const size_t nb = s_.size();
  const bool first = samples_ == 1;
  for (size_t i = 0; i < nb; ++i) {  // the rfe's middle: the middle of its chord A_i A_{i+1}
    const double c = seabed_.clearance(0.5 * (o.points[i] + o.points[i + 1]));
    clearance_.min[i] = first ? c : std::min(clearance_.min[i], c);
    clearance_.max[i] = first ? c : std::max(clearance_.max[i], c);
  }
  for (size_t j = 0; j < o.points.size(); ++j) {
    if (!(seabed_.clearance(o.points[j]) < 0.0)) continue;
    const double s = s_point_[j];
    td_min_ = td_samples_ == 0 ? s : std::min(td_min_, s);
    td_max_ = td_samples_ == 0 ? s : std::max(td_max_, s);
    ++td_samples_;
    break;
  }
}

void RangeGraph::restart(const RunOutputs& first) {
  samples_ = 0;
  td_samples_ = 0;
  td_min_ = td_max_ = kNaN;
  std::copy(first.axial_force.begin(), first.axial_force.end(), tension_.min.begin());
  std::copy(first.axial_force.begin(), first.axial_force.end(), tension_.max.begin());
  std::copy(first.bending_moment.begin(), first.bending_moment.end(), moment_.min.begin());
  std::copy(first.bending_moment.begin(), first.bending_moment.end(), moment_.max.begin());
  std::copy(first.curvature.begin(), first.curvature.end(), curvature_.min.begin());
  std::copy(first.curvature.begin(), first.curvature.end(), curvature_.max.begin());
  add(first);  // the clearance starts from its first sample there
}

double RangeGraph::tensionMaxS() const { return argMax(tension_.max, s_); }

double RangeGraph::curvatureMax() const {
  return curvature_.max.empty() ? kNaN : *std::max_element(curvature_.max.begin(), curvature_.max.end());
}

double RangeGraph::curvatureMaxS() const { return argMax(curvature_.max, s_joint_); }

}  // namespace riser_sim
