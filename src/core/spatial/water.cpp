#include "riser_sim/spatial/water.h"

#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace riser_sim {
namespace spatial {

namespace {

// The planar kinematics of the waves alone: no current, the surface at 0 (Water3 passes heights).
WaterSpec wavesOnly(const WaterSpec& spec) {
  WaterSpec w = spec;
  w.current = CurrentSpec();
  w.surface = 0.0;
  w.waves.heading = 0.0;
  return w;
}

bool vertical(const Vec3& g) { return g.x() == 0.0 && g.y() == 0.0 && g.z() < 0.0; }

std::atomic<unsigned long long> g_next_id{1};

// The per-thread table of the last wave samples (at()). 1024 slots: one evaluation of n <= 500 wet parts fits.
struct Sample {
  unsigned long long id = 0;
  double t = 0.0;
  Vec3 p, v, a;
};
constexpr std::size_t kSlots = 1024;
thread_local Sample t_samples[kSlots];

std::uint64_t bits(double x) {
  std::uint64_t u;
  std::memcpy(&u, &x, sizeof u);
  return u;
}

std::size_t slot(unsigned long long id, const Vec3& p, double t) {
  std::uint64_t h = id * 0x9E3779B97F4A7C15ull;
  for (double x : {p.x(), p.y(), p.z(), t}) h = (h ^ bits(x)) * 0xBF58476D1CE4E5B9ull, h ^= h >> 31;
  return static_cast<std::size_t>(h & (kSlots - 1));
}

}  // namespace

Water3::Water3(const WaterSpec& spec, const Vec3& gravity)
    : spec_(spec),
      up_(gravity.norm() > 0.0 ? Vec3(-gravity.normalized()) : Vec3::UnitZ()),
      waves_(wavesOnly(spec), gravity.norm()) {
  const CurrentSpec& c = spec.current;
  moving_ = c.velocity.norm() > 0.0 || c.acceleration.norm() > 0.0 || !c.profile.empty() || spec.waves.active();
  if (spec.waves.active() && !vertical(gravity))
    throw std::invalid_argument("environment.waves: need gravity along -z (the waves' heading is horizontal)");
  if (!c.profile.empty() && gravity.norm() > 0.0 && !vertical(gravity))
    throw std::invalid_argument("environment.current.profile: needs gravity along -z (the profile is horizontal)");
  wave_dir_ = Vec3(std::cos(spec.waves.heading), std::sin(spec.waves.heading), 0.0);
  id_ = g_next_id.fetch_add(1);
}

Water3 Water3::steady(double t) const {
  WaterSpec s = spec_;
  s.waves.height = 0.0;
  s.waves.significant_height = 0.0;
  CurrentSpec& c = s.current;
  c.velocity += c.acceleration * t;
  for (CurrentSpec::Point& p : c.profile) p.vx += c.acceleration.x() * t, p.vy += c.acceleration.y() * t;
  c.acceleration.setZero();
  return Water3(s, -up_);  // no waves: the gravity's size is not used
}

void Water3::at(const Vec3& p, double t, Vec3& v, Vec3& a) const {
  if (!spec_.waves.active()) return compute(p, t, v, a);
  Sample& s = t_samples[slot(id_, p, t)];
  if (s.id == id_ && s.t == t && s.p == p) {
    v = s.v;
    a = s.a;
    return;
  }
  compute(p, t, v, a);
  s.id = id_, s.t = t, s.p = p, s.v = v, s.a = a;
}

void Water3::compute(const Vec3& p, double t, Vec3& v, Vec3& a) const {
  v.setZero();
  a.setZero();
  const double z = height(p);
  if (z > 0.0) return;
  const CurrentSpec& c = spec_.current;
  v = c.velocity + c.acceleration * t;
  a = c.acceleration;
  if (!c.profile.empty()) {
    const double d = -z;
    double vx = c.profile.front().vx, vy = c.profile.front().vy;
    if (d >= c.profile.back().depth) {
      vx = c.profile.back().vx, vy = c.profile.back().vy;
    } else {
      for (size_t i = 1; i < c.profile.size(); ++i)
        if (d < c.profile[i].depth) {
          const auto& p0 = c.profile[i - 1];
          const auto& p1 = c.profile[i];
          const double f = d <= p0.depth ? 0.0 : (d - p0.depth) / (p1.depth - p0.depth);
          vx = p0.vx + f * (p1.vx - p0.vx), vy = p0.vy + f * (p1.vy - p0.vy);
          break;
        }
    }
    v.x() = vx + c.acceleration.x() * t;
    v.y() = vy + c.acceleration.y() * t;
  }
  if (spec_.waves.active()) {
    Vec2 vw, aw;
    waves_.at(Vec2(wave_dir_.dot(p), z), t, vw, aw);
    v += vw.x() * wave_dir_ + vw.y() * up_;
    a += aw.x() * wave_dir_ + aw.y() * up_;
  }
}

WetPart3 wetPart3(const Model& line, const BodyKinematics3& b, int i, int part, const Water3& water) {
  const Rfe& r = line.rfe(i);
  const double start = part == 0 ? 0.0 : r.length1, len = part == 0 ? r.length1 : r.length2;
  const double kappa = part == 0 ? 0.0 : 1.0;
  const double h0 = water.height(b.point(start, kappa)), h1 = h0 + len * water.up().dot(b.e);
  double frac, cen;
  submerged(h0, h1, 0.0, frac, cen);
  return WetPart3{frac * len, start + cen * len, kappa};
}

}  // namespace spatial
}  // namespace riser_sim
