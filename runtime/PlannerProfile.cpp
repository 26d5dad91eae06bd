// Velocity profiles of the planner: jerk-limited S-curve velocity changes, ramps (change, cruise,
// change) over a run of moves, and slices of a ramp for each move (docs/PLANNER.md).
#include "runtime/Planner.h"

#include <algorithm>
#include <cmath>

namespace ncc {

namespace {

// Shape of a symmetric velocity change of |dv|: jerk phases of tj, a constant-acceleration phase
// of ta at peak acceleration apk (tj = 0 without a jerk limit).
struct ChangeShape {
  double sign, tj, ta, apk;
};

ChangeShape changeShape(double dv, double a, double j) {
  double adv = std::fabs(dv);
  ChangeShape c{dv < 0 ? -1.0 : 1.0, 0, 0, a};
  if (std::isinf(j) || adv >= a * a / j) {
    c.tj = std::isinf(j) ? 0 : a / j;
    c.ta = std::max(0.0, adv / a - c.tj);
  } else {
    c.tj = std::sqrt(adv / j);
    c.apk = j * c.tj;
  }
  return c;
}

// Position, speed and acceleration after time tau into a velocity change of dv from vStart.
void changeAt(double vStart, double dv, double a, double j, double tau, double &s, double &v, double &acc) {
  ChangeShape c = changeShape(dv, a, j);
  s = 0;
  v = vStart;
  acc = 0;
  if (tau <= 0 || dv == 0) return;
  double t1 = std::min(tau, c.tj);  // jerk rising
  if (t1 > 0) {
    s += v * t1 + c.sign * j * t1 * t1 * t1 / 6;
    v += c.sign * j * t1 * t1 / 2;
    acc = c.sign * j * t1;
  }
  if (tau <= c.tj) return;
  double t2 = std::min(tau - c.tj, c.ta);  // constant acceleration
  if (t2 > 0) {
    s += v * t2 + c.sign * c.apk * t2 * t2 / 2;
    v += c.sign * c.apk * t2;
  }
  acc = c.sign * c.apk;
  if (tau <= c.tj + c.ta) return;
  if (c.tj <= 0) { acc = 0; return; }
  double t3 = std::min(tau - c.tj - c.ta, c.tj);  // jerk falling
  s += v * t3 + c.sign * (c.apk * t3 * t3 / 2 - j * t3 * t3 * t3 / 6);
  v += c.sign * (c.apk * t3 - j * t3 * t3 / 2);
  acc = c.sign * (c.apk - j * t3);
}

// Time within [0, hi] at which v t + k2 t^2 + k3 t^3 reaches target (increasing there): Newton
// steps safeguarded by bisection, from the root without the cubic term (a few steps suffice).
double solvePhase(double v, double k2, double k3, double target, double hi) {
  double lo = 0, t;
  if (v <= 0 && k2 <= 0) t = k3 > 0 ? std::cbrt(target / k3) : 0.5 * hi;  // from rest: exact
  else t = 2 * target / (v + std::sqrt(std::max(0.0, v * v + 4 * k2 * target)));
  t = std::clamp(t, 0.0, hi);
  for (int i = 0; i < 60; ++i) {
    double f = ((k3 * t + k2) * t + v) * t - target, d = (3 * k3 * t + 2 * k2) * t + v;
    (f > 0 ? hi : lo) = t;
    double next = d > 0 ? t - f / d : -1;
    if (!(next >= lo && next <= hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - t) <= 1e-13 * next) return next;
    t = next;
  }
  return t;
}

// Time into a velocity change of dv from vStart at which distance d is covered.
double changeTimeAt(double vStart, double dv, double a, double j, double d) {
  if (d <= 0) return 0;
  ChangeShape c = changeShape(dv, a, j);
  double v = vStart;
  if (c.tj > 0) {
    double s1 = v * c.tj + c.sign * j * c.tj * c.tj * c.tj / 6;
    if (d <= s1) return solvePhase(v, 0, c.sign * j / 6, d, c.tj);
    d -= s1;
    v += c.sign * j * c.tj * c.tj / 2;
  }
  double s2 = v * c.ta + c.sign * c.apk * c.ta * c.ta / 2;
  if (d <= s2 || c.tj <= 0) {
    // v t + sign apk t^2 / 2 = d, the root in the phase, in the cancellation-free form.
    double disc = std::max(0.0, v * v + 2 * c.sign * c.apk * d);
    double t = v + std::sqrt(disc) > 0 ? 2 * d / (v + std::sqrt(disc)) : 0;
    return c.tj + std::min(t, c.ta);
  }
  d -= s2;
  v += c.sign * c.apk * c.ta;
  return c.tj + c.ta + solvePhase(v, c.sign * c.apk / 2, -c.sign * j / 6, d, c.tj);
}

}  // namespace

double velocityChangeTime(double dv, double a, double j) {
  dv = std::fabs(dv);
  if (dv <= 0) return 0;
  if (std::isinf(j)) return dv / a;
  return dv >= a * a / j ? dv / a + a / j : 2 * std::sqrt(dv / j);
}

double velocityChangeDistance(double v0, double v1, double a, double j) {
  // A symmetric S-curve is point-symmetric about its midpoint: mean speed = (v0 + v1) / 2.
  return 0.5 * (v0 + v1) * velocityChangeTime(v1 - v0, a, j);
}

double maxReachableSpeed(double v, double len, double a, double j) {
  if (len <= 0) return v;
  if (!std::isinf(j)) {
    double dvStar = a * a / j;  // smallest change that reaches full acceleration
    double dStar = (2 * v + dvStar) * a / j;
    if (len <= dStar) {
      // dv = j s^2 where j s^3 + 2 v s = len (increasing, convex for s > 0): Halley steps from
      // an upper bound (each term alone reaching len) converge cubically.
      double s = std::cbrt(len / j);
      if (v > 0) s = std::min(s, len / (2 * v));
      for (int i = 0; i < 40; ++i) {
        double f = j * s * s * s + 2 * v * s - len, d1 = 3 * j * s * s + 2 * v, d2 = 6 * j * s;
        double step = f * d1 / (d1 * d1 - 0.5 * f * d2);
        s -= step;
        if (std::fabs(step) <= 1e-13 * s) break;
      }
      return v + j * s * s;
    }
  }
  double k = std::isinf(j) ? 0 : a * a / j;
  double B = 2 * v + k, C = 2 * v * k - 2 * len * a;  // dv^2 + B dv + C = 0, C < 0
  return v + (-2 * C) / (B + std::sqrt(B * B - 4 * C));
}

VelocityProfile planProfile(double len, double v0, double v1, double vmax, double a, double j) {
  VelocityProfile p;
  p.rampLength = len;
  p.accel = a;
  p.jerk = j;
  v0 = std::min(v0, vmax);
  v1 = std::min(v1, vmax);
  p.rampV0 = v0;
  p.rampV1 = v1;
  if (len <= 0) {
    p.rampVp = std::max(v0, v1);
    p.whole();
    return p;
  }
  auto need = [&](double vp) {
    return velocityChangeDistance(v0, vp, a, j) + velocityChangeDistance(vp, v1, a, j);
  };
  double vp = vmax;
  if (need(vmax) > len) {
    double lo = std::max(v0, v1), hi = vmax;
    // Peak of a trapezoid: exact without a jerk limit, an upper estimate with one.
    vp = std::clamp(std::sqrt(std::max(0.0, a * len + 0.5 * (v0 * v0 + v1 * v1))), lo, hi);
    if (!std::isinf(j)) {
      // Safeguarded Newton on the (increasing) distance needed to reach the peak and come back.
      auto slope = [&](double from, double to) {  // d/d(to) of velocityChangeDistance(from, to)
        double dv = to - from, t = velocityChangeTime(dv, a, j);
        double dt = dv >= a * a / j ? 1 / a : (dv > 0 ? 1 / std::sqrt(dv * j) : INFINITY);
        return 0.5 * t + 0.5 * (from + to) * dt;
      };
      for (int i = 0; i < 60; ++i) {
        double f = need(vp) - len;
        if (std::fabs(f) <= 1e-13 * len || hi - lo <= 1e-13 * hi) break;
        (f > 0 ? hi : lo) = vp;
        double next = vp - f / (slope(v0, vp) + slope(v1, vp));
        vp = next > lo && next < hi ? next : 0.5 * (lo + hi);
      }
    }
  }
  p.rampVp = vp;
  p.tAcc = velocityChangeTime(vp - v0, a, j);
  p.tDec = velocityChangeTime(vp - v1, a, j);
  double rest = len - need(vp);
  if (rest > 0 && vp > 0) p.tCruise = rest / vp;
  p.whole();
  return p;
}

void VelocityProfile::rampAt(double t, double &s, double &v, double &a) const {
  if (t <= 0) { s = 0; v = rampV0; a = 0; return; }
  if (t < tAcc) { changeAt(rampV0, rampVp - rampV0, accel, jerk, t, s, v, a); return; }
  double sAcc = 0.5 * (rampV0 + rampVp) * tAcc;
  if (t < tAcc + tCruise) { s = sAcc + rampVp * (t - tAcc); v = rampVp; a = 0; return; }
  double sd;
  changeAt(rampVp, rampV1 - rampVp, accel, jerk, std::min(t - tAcc - tCruise, tDec), sd, v, a);
  s = std::min(rampLength, sAcc + rampVp * tCruise + sd);
  if (t >= rampDuration()) a = 0;
}

double VelocityProfile::rampTimeAt(double s) const {
  if (s <= 0) return 0;
  double sAcc = 0.5 * (rampV0 + rampVp) * tAcc;
  if (s <= sAcc) return changeTimeAt(rampV0, rampVp - rampV0, accel, jerk, s);
  double sCruise = rampVp * tCruise;
  if (s <= sAcc + sCruise) return tAcc + (s - sAcc) / rampVp;
  if (s >= rampLength) return rampDuration();
  return tAcc + tCruise + std::min(tDec, changeTimeAt(rampVp, rampV1 - rampVp, accel, jerk, s - sAcc - sCruise));
}

void VelocityProfile::whole() {
  tBegin = sBegin = 0;
  tSpan = rampDuration();
  length = rampLength;
  v0 = rampV0;
  v1 = rampV1;
  vp = std::max({rampV0, rampVp, rampV1});
}

double VelocityProfile::slice(double sFrom, double sTo, double tFrom, double vFrom) {
  const bool toEnd = sTo >= rampLength;
  double tTo = toEnd ? rampDuration() : std::max(tFrom, rampTimeAt(sTo));
  sBegin = sFrom;
  length = sTo - sFrom;
  tBegin = tFrom;
  tSpan = tTo - tFrom;
  v0 = vFrom;
  double s, a;
  if (toEnd) v1 = rampV1;
  else rampAt(tTo, s, v1, a);
  // The ramp's speed rises, cruises, falls: the slice's peak is the cruise when it spans it.
  vp = tFrom <= tAcc + tCruise && tTo >= tAcc ? rampVp : std::max(v0, v1);
  return tTo;
}

void VelocityProfile::at(double t, double &s, double &v, double &a) const {
  rampAt(tBegin + std::clamp(t, 0.0, tSpan), s, v, a);
  s = std::clamp(s - sBegin, 0.0, length);
}

void VelocityProfile::at(double t, double &s, double &v) const {
  double a;
  at(t, s, v, a);
}

}  // namespace ncc
