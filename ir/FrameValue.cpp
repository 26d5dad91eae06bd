#include "ir/FrameValue.h"
#include "ir/Mat3.h"
#include "ir/Value.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstring>

namespace ncc {

static constexpr double kDeg = M_PI / 180.0;
static const char *const kAxisNames[kFrameAxes] = {"X", "Y", "Z", "A", "B", "C"};
static const char *const kCompNames[] = {"TR", "FI", "RT", "SC", "MI"};

bool FrameValue::operator==(const FrameValue &o) const {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (L[i][j] != o.L[i][j]) return false;
  for (int i = 0; i < kFrameAxes; ++i)
    if (coarse[i] != o.coarse[i] || fine[i] != o.fine[i]) return false;
  for (int i = 0; i < 3; ++i)
    if (rotary[i] != o.rotary[i]) return false;
  return true;
}

static void mul(const double a[3][3], const double b[3][3], double out[3][3]) {
  double r[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
  std::memcpy(out, r, sizeof r);
}

static void apply(const double m[3][3], const double *v, double *out) {
  double r[3];
  for (int i = 0; i < 3; ++i) r[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
  std::memcpy(out, r, sizeof r);
}

FrameValue frameChain(const FrameValue &a, const FrameValue &b) {
  FrameValue r;
  mul(a.L, b.L, r.L);
  apply(a.L, b.coarse, r.coarse);
  apply(a.L, b.fine, r.fine);
  for (int i = 0; i < 3; ++i) r.coarse[i] += a.coarse[i], r.fine[i] += a.fine[i];
  for (int i = 0; i < 3; ++i) {
    r.rotary[i] = a.rotary[i] * b.rotary[i];
    r.coarse[3 + i] = a.coarse[3 + i] + a.rotary[i] * b.coarse[3 + i];
    r.fine[3 + i] = a.fine[3 + i] + a.rotary[i] * b.fine[3 + i];
  }
  return r;
}

FrameValue frameInverse(const FrameValue &f) {
  FrameValue r;
  mat3Inverse(f.L, r.L);
  apply(r.L, f.coarse, r.coarse);
  apply(r.L, f.fine, r.fine);
  for (int i = 0; i < 3; ++i) r.coarse[i] = -r.coarse[i], r.fine[i] = -r.fine[i];
  for (int i = 0; i < 3; ++i) {
    r.rotary[i] = 1 / f.rotary[i];
    r.coarse[3 + i] = -f.coarse[3 + i] / f.rotary[i];
    r.fine[3 + i] = -f.fine[3 + i] / f.rotary[i];
  }
  return r;
}

// sin and cos of degrees, exact at multiples of 90° (CROT(Z,90) is an exact quarter turn).
static void sinCos(double deg, double &s, double &c) {
  double q = deg / 90.0;
  if (q == std::trunc(q) && std::fabs(q) < 1e15) {
    static const double kS[4] = {0, 1, 0, -1}, kC[4] = {1, 0, -1, 0};
    int k = (int)std::fmod(std::fmod(q, 4.0) + 4.0, 4.0);
    s = kS[k], c = kC[k];
    return;
  }
  s = std::sin(deg * kDeg), c = std::cos(deg * kDeg);
}

void frameRotation(double x, double y, double z, double R[3][3]) {
  double ca, sa, cb, sb, cg, sg;
  sinCos(x, sa, ca), sinCos(y, sb, cb), sinCos(z, sg, cg);
  double r[3][3] = {{cg * cb, cg * sb * sa - sg * ca, cg * sb * ca + sg * sa},
                    {sg * cb, sg * sb * sa + cg * ca, sg * sb * ca - cg * sa},
                    {-sb, cb * sa, cb * ca}};
  std::memcpy(R, r, sizeof r);
}

bool frameSolidRotation(const bool given[3], const double angle[3], double R[3][3], std::string &error) {
  int count = given[0] + given[1] + given[2];
  if (count > 2) {
    error = "the orientation of a plane takes at most two solid angles (X Y, Y Z or Z X)";
    return false;
  }
  if (count < 2) {
    frameRotation(given[0] ? angle[0] : 0, given[1] ? angle[1] : 0, given[2] ? angle[2] : 0, R);
    return true;
  }
  int f = given[0] && given[1] ? 0 : given[1] && given[2] ? 1 : 2, s = (f + 1) % 3, t = (f + 2) % 3;
  double sa, ca, sb, cb;
  sinCos(angle[f], sa, ca), sinCos(angle[s], sb, cb);
  // In the right-handed basis (f, s, t): the new f axis and the line of the plane in the s-t plane.
  const double u[3] = {cb, 0, -sb}, v[3] = {0, ca, sa};
  double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (len < 1e-12) {
    error = "the solid angles span no plane (both are 90°)";
    return false;
  }
  for (double &c : n) c /= len;
  const double w[3] = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};  // t × f
  const int axis[3] = {f, s, t};
  for (int i = 0; i < 3; ++i)  // columns: the new axes in the old system, back from (f, s, t)
    R[axis[i]][f] = u[i], R[axis[i]][s] = w[i], R[axis[i]][t] = n[i];
  return true;
}

FrameValue frameCompose(const FrameParts &p) {
  FrameValue f;
  double R[3][3];
  frameRotation(p.rt[0], p.rt[1], p.rt[2], R);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) f.L[i][j] = R[i][j] * p.sc[j] * (p.mi[j] ? -1 : 1);
  for (int i = 0; i < kFrameAxes; ++i) f.coarse[i] = p.tr[i], f.fine[i] = p.fi[i];
  for (int i = 0; i < 3; ++i) f.rotary[i] = p.sc[3 + i] * (p.mi[3 + i] ? -1 : 1);
  return f;
}

// Decomposed angles and factors carry rounding noise from atan2/asin/hypot; rounding them (to
// 1e-10 degrees, 12 significant digits) lets what a program wrote read back (CROT(Z,30) gives
// RT 30, not 29.999999999999996), far below any machine's resolution.
static double snapAngle(double deg) { return std::round(deg * 1e10) / 1e10; }
static double snapFactor(double f) {
  if (f == 0) return f;
  double k = std::pow(10.0, 11 - std::floor(std::log10(std::fabs(f))));
  return std::round(f * k) / k;
}

bool frameDecompose(const FrameValue &f, FrameParts &out, std::string &error) {
  FrameParts p;
  for (int i = 0; i < kFrameAxes; ++i) p.tr[i] = f.coarse[i], p.fi[i] = f.fine[i];
  for (int i = 0; i < 3; ++i) p.sc[3 + i] = std::fabs(f.rotary[i]), p.mi[3 + i] = f.rotary[i] < 0;
  double s[3];
  for (int j = 0; j < 3; ++j) s[j] = std::hypot(f.L[0][j], f.L[1][j], f.L[2][j]);
  // L = R · diag(d) with d_j = ±s_j: of the sign choices that leave a proper rotation, the
  // fewest mirrored axes (none when det L > 0, else one), then the smallest rotation (largest
  // trace). So CMIRROR(X, Y) reads back as RT Z180: the same frame.
  const int order[4] = {0, 1, 2, 4};
  double best = -1e300, R[3][3] = {};
  int bestMask = -1;
  for (int mask : order) {
    double d[3], r[3][3];
    for (int j = 0; j < 3; ++j) d[j] = (mask >> j & 1) ? -s[j] : s[j];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r[i][j] = f.L[i][j] / d[j];
    if (mat3Det(r) <= 0) continue;
    double tr = r[0][0] + r[1][1] + r[2][2];
    if (tr > best + 1e-12) best = tr, bestMask = mask, std::memcpy(R, r, sizeof r);
    if (mask == 0) break;  // a proper rotation without mirrors
  }
  for (int j = 0; j < 3; ++j) p.sc[j] = snapFactor(s[j]), p.mi[j] = bestMask >= 0 && (bestMask >> j & 1);
  double sb = -R[2][0];
  double beta = std::asin(std::fmax(-1.0, std::fmin(1.0, sb)));
  double alpha, gamma;
  if (std::fabs(std::cos(beta)) > 1e-9) {
    alpha = std::atan2(R[2][1], R[2][2]);
    gamma = std::atan2(R[1][0], R[0][0]);
  } else {  // gimbal lock: the X and Z rotations act alike; all of it goes to Z
    alpha = 0;
    gamma = std::atan2(-R[0][1], R[1][1]);
  }
  p.rt[0] = snapAngle(alpha / kDeg), p.rt[1] = snapAngle(beta / kDeg), p.rt[2] = snapAngle(gamma / kDeg);
  for (double &a : p.rt)
    if (a == -180.0) a = 180.0;
  // Exact only when composing the parts gives the matrix back.
  FrameValue back = frameCompose(p);
  double scale = 1;
  for (auto &row : f.L)
    for (double v : row) scale = std::fmax(scale, std::fabs(v));
  bool ok = bestMask >= 0 && s[0] > 0 && s[1] > 0 && s[2] > 0;
  for (int i = 0; ok && i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (std::fabs(back.L[i][j] - f.L[i][j]) > 1e-9 * scale) ok = false;
  if (!ok) {
    error = "the frame combines a rotation with unequal scale factors: it has no RT/SC/MI components";
    return false;
  }
  out = p;
  return true;
}

bool frameAxis(std::string_view name, int &axis) {
  if (name.size() != 1) return false;
  char c = (char)std::toupper((unsigned char)name[0]);
  for (int i = 0; i < kFrameAxes; ++i)
    if (kAxisNames[i][0] == c) return axis = i, true;
  return false;
}

bool frameComp(std::string_view name, FrameComp &out) {
  if (name.size() != 2) return false;
  char a = (char)std::toupper((unsigned char)name[0]), b = (char)std::toupper((unsigned char)name[1]);
  for (unsigned i = 0; i < sizeof kCompNames / sizeof *kCompNames; ++i)
    if (kCompNames[i][0] == a && kCompNames[i][1] == b) return out = (FrameComp)i, true;
  return false;
}

const char *frameAxisName(int axis) { return kAxisNames[axis]; }

static std::string number(double v) {
  v = std::round(v * 1e9) / 1e9;
  return numberText(v == 0 ? 0.0 : v);
}

std::string frameText(const FrameValue &f) {
  if (f.identity()) return "identity";
  FrameParts p;
  std::string err, out;
  auto part = [&](const char *what, auto &&value, auto &&keep, int axes) {
    std::string s;
    for (int i = 0; i < axes; ++i)
      if (keep(i)) s += fmt::format(" {}{}", kAxisNames[i], value(i));
    if (s.empty()) return;
    if (!out.empty()) out += ' ';
    out += what;
    out += s;
  };
  if (!frameDecompose(f, p, err)) {
    out = "matrix";
    for (auto &row : f.L) out += fmt::format(" [{} {} {}]", number(row[0]), number(row[1]), number(row[2]));
    for (int i = 0; i < 3; ++i) p.sc[3 + i] = std::fabs(f.rotary[i]), p.mi[3 + i] = f.rotary[i] < 0;
    for (int i = 0; i < 3; ++i) p.sc[i] = 1, p.mi[i] = false, p.rt[i] = 0;
    for (int i = 0; i < kFrameAxes; ++i) p.tr[i] = f.coarse[i], p.fi[i] = f.fine[i];
  }
  part("TR", [&](int i) { return number(p.tr[i]); }, [&](int i) { return number(p.tr[i]) != "0"; }, kFrameAxes);
  part("FI", [&](int i) { return number(p.fi[i]); }, [&](int i) { return number(p.fi[i]) != "0"; }, kFrameAxes);
  part("RT", [&](int i) { return number(p.rt[i]); }, [&](int i) { return number(p.rt[i]) != "0"; }, 3);
  part("SC", [&](int i) { return number(p.sc[i]); }, [&](int i) { return number(p.sc[i]) != "1"; }, kFrameAxes);
  part("MI", [](int) { return ""; }, [&](int i) { return p.mi[i]; }, kFrameAxes);
  return out.empty() ? "identity" : out;  // within rounding of the identity
}

static uint64_t hashFrame(const FrameValue &f) {
  const unsigned char *b = reinterpret_cast<const unsigned char *>(&f);
  uint64_t h = 1469598103934665603ull;
  for (size_t i = 0; i < sizeof f; ++i) h = (h ^ b[i]) * 1099511628211ull;
  return h;
}

FramePool::FramePool() {
  frames_.emplace_back();
  index_.emplace(hashFrame(frames_[0]), 0);
}

bool FramePool::intern(const FrameValue &f, double &out, std::string &error) {
  uint64_t h = hashFrame(f);
  for (auto [it, end] = index_.equal_range(h); it != end; ++it)
    if (frames_[it->second] == f) return out = bitsValue(kFrameTag | it->second), true;
  for (auto &row : f.L)
    for (double v : row)
      if (!std::isfinite(v)) return error = "a frame component is not a finite number", false;
  for (int i = 0; i < kFrameAxes; ++i)
    if (!std::isfinite(f.coarse[i]) || !std::isfinite(f.fine[i]))
      return error = "a frame component is not a finite number", false;
  if (frames_.size() >= kMaxPoolFrames) {
    error = fmt::format("frame pool limit exceeded: more than {} distinct frames in one run", kMaxPoolFrames);
    return false;
  }
  uint32_t i = (uint32_t)frames_.size();
  frames_.push_back(f);
  index_.emplace(h, i);
  out = bitsValue(kFrameTag | i);
  return true;
}

const FrameValue &FramePool::get(double v) const {
  if (!isFrame(v)) return frames_[0];
  uint64_t i = valueBits(v) & ~kStringTagMask;
  return i < frames_.size() ? frames_[i] : frames_[0];
}

}  // namespace ncc
