#include "contact/rigid_tool.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace vs {

RigidTool::RigidTool(std::string name, ToolKind kind, std::vector<ProfilePrimitive> profile,
                     Eigen::Vector2d velocity, double friction)
    : name_(std::move(name)),
      kind_(kind),
      profile_(std::move(profile)),
      velocity_(velocity),
      friction_(friction) {}

bool RigidTool::sticking() const { return friction_ == std::numeric_limits<double>::infinity(); }

namespace {

ClosestPoint closest_on(const ProfilePrimitive& p, const Eigen::Vector2d& x) {
  ClosestPoint c;
  if (p.kind == ProfilePrimitive::Kind::kSegment) {
    const Eigen::Vector2d d = p.p1 - p.p0;
    const double tau = std::clamp((x - p.p0).dot(d) / d.squaredNorm(), 0.0, 1.0);
    c.point = p.p0 + tau * d;
    c.normal = p.normal;
  } else {
    const Eigen::Vector2d rel = x - p.centre;
    double a = std::atan2(rel.y(), rel.x());
    // Bring a into [angle0 - pi, angle0 + pi) so the clamp picks the nearer end.
    const double mid = 0.5 * (p.angle0 + p.angle1);
    while (a < mid - std::numbers::pi) a += 2.0 * std::numbers::pi;
    while (a >= mid + std::numbers::pi) a -= 2.0 * std::numbers::pi;
    a = std::clamp(a, p.angle0, p.angle1);
    const Eigen::Vector2d radial(std::cos(a), std::sin(a));
    c.point = p.centre + p.radius * radial;
    c.normal = p.convex ? radial : Eigen::Vector2d(-radial);
  }
  const Eigen::Vector2d gap = x - c.point;
  const double along = gap.dot(c.normal);
  const double dist = gap.norm();
  // Inside the primitive's range the gap is along the normal; past an end, keep the side sign.
  c.distance =
      (dist - std::abs(along) < 1e-12 * (1.0 + dist)) ? along : (along >= 0.0 ? dist : -dist);
  return c;
}

}  // namespace

ClosestPoint RigidTool::closest(const Eigen::Vector2d& x) const {
  const Eigen::Vector2d local = x - offset_;
  ClosestPoint best;
  double best_abs = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < profile_.size(); ++i) {
    ClosestPoint c = closest_on(profile_[i], local);
    const double a = (local - c.point).norm();
    if (a < best_abs - 1e-12) {
      best_abs = a;
      best = c;
      best.primitive = static_cast<int>(i);
    }
  }
  best.point += offset_;
  return best;
}

double RigidTool::contact_time(const Eigen::Vector2d& x, const Eigen::Vector2d& v, double h,
                               double horizon) const {
  const double inf = std::numeric_limits<double>::infinity();
  const Eigen::Vector2d rel = v - velocity_;  // node velocity relative to the tool
  const double speed = rel.norm();
  const double g0 = gap(x, h);
  // Already touching (or penetrated): contact detection, not the step size, deals with it.
  if (g0 <= 0.0) return inf;
  if (speed == 0.0 || g0 > speed * horizon) return inf;  // cannot close the gap in time
  auto g = [&](double t) { return closest(x + rel * t).distance - 0.5 * h; };
  // Sample for the first sign change, then bisect (the trajectory is a straight line relative
  // to the tool; paper eq. 53-56 solve the same root by fixed-point iteration).
  constexpr int kSamples = 16;
  double t_prev = 0.0, g_prev = g0;
  for (int k = 1; k <= kSamples; ++k) {
    const double t = horizon * k / kSamples;
    const double gt = g(t);
    if (gt <= 0.0) {
      double lo = t_prev, hi = t, glo = g_prev;
      for (int it = 0; it < 60 && hi - lo > 1e-12 * horizon; ++it) {
        const double mid = 0.5 * (lo + hi);
        const double gm = g(mid);
        if (gm > 0.0) {
          lo = mid;
          glo = gm;
        } else {
          hi = mid;
        }
      }
      (void)glo;
      return hi;
    }
    t_prev = t;
    g_prev = gt;
  }
  return inf;
}

namespace {

ProfilePrimitive segment(Eigen::Vector2d a, Eigen::Vector2d b, Eigen::Vector2d normal) {
  ProfilePrimitive p;
  p.kind = ProfilePrimitive::Kind::kSegment;
  p.p0 = a;
  p.p1 = b;
  p.normal = normal;
  return p;
}

ProfilePrimitive arc(Eigen::Vector2d centre, double radius, double a0, double a1, bool convex) {
  ProfilePrimitive p;
  p.kind = ProfilePrimitive::Kind::kArc;
  p.centre = centre;
  p.radius = radius;
  p.angle0 = a0;
  p.angle1 = a1;
  p.convex = convex;
  return p;
}

}  // namespace

std::vector<RigidTool> make_tools(const Scene& scene) {
  const double h0 = scene.blank.thickness_mm;
  const double extent = 4.0 * scene.blank.radius_mm + scene.process.punch_travel_mm;
  const double pi = std::numbers::pi;
  const Eigen::Vector2d punch_velocity(0.0, scene.process.punch_speed_mm_per_s);
  std::vector<RigidTool> tools;
  for (const ToolSpec& t : scene.tools) {
    std::vector<ProfilePrimitive> prof;
    Eigen::Vector2d vel = Eigen::Vector2d::Zero();
    switch (t.kind) {
      case ToolKind::kHemisphericalPunch: {
        // Apex touches the lower sheet surface at travel 0.
        const double R = t.radius_mm;
        const Eigen::Vector2d c(0.0, -0.5 * h0 - R);
        prof.push_back(arc(c, R, 0.0, 0.5 * pi, true));
        prof.push_back(segment({R, c.y() - extent}, {R, c.y()}, {1.0, 0.0}));
        vel = punch_velocity;
        break;
      }
      case ToolKind::kFlatPunch: {
        const double R = t.radius_mm, rho = t.profile_radius_mm;
        const double top = -0.5 * h0;
        prof.push_back(segment({0.0, top}, {R - rho, top}, {0.0, 1.0}));
        prof.push_back(arc({R - rho, top - rho}, rho, 0.0, 0.5 * pi, true));
        prof.push_back(segment({R, top - rho - extent}, {R, top - rho}, {1.0, 0.0}));
        vel = punch_velocity;
        break;
      }
      case ToolKind::kDie: {
        // Shoulder torus tangent to the die face (z = h0/2) and to the opening wall r = radius.
        const double Ro = t.radius_mm, rho = t.profile_radius_mm;
        const double face = 0.5 * h0;
        prof.push_back(segment({Ro + rho, face}, {Ro + rho + extent, face}, {0.0, -1.0}));
        prof.push_back(arc({Ro + rho, face + rho}, rho, pi, 1.5 * pi, true));
        prof.push_back(segment({Ro, face + rho}, {Ro, face + rho + extent}, {-1.0, 0.0}));
        break;
      }
      case ToolKind::kBlankHolder: {
        // A force holder is not a surface (the model spreads its force over the flange). A
        // fixed-gap holder is a flat face gap_mm below the die face, under the flange: from the
        // start of the die's flat face (die radius + shoulder radius) outwards.
        if (!(t.gap_mm > 0.0)) continue;
        double inner = 0.0;
        for (const ToolSpec& d : scene.tools) {
          if (d.kind == ToolKind::kDie) inner = d.radius_mm + d.profile_radius_mm;
        }
        const double top = 0.5 * h0 - t.gap_mm;
        prof.push_back(segment({inner, top}, {inner + extent, top}, {0.0, 1.0}));
        break;
      }
    }
    tools.emplace_back(t.name, t.kind, std::move(prof), vel, t.friction);
  }
  return tools;
}

}  // namespace vs
