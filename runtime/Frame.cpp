#include "runtime/Frame.h"
#include "ir/Mat3.h"

#include <cmath>

namespace ncc {

Vec3 Affine::applyLinear(const Vec3 &v) const {
  Vec3 r;
  for (int i = 0; i < 3; ++i) r[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
  return r;
}

Vec3 Affine::apply(const Vec3 &p) const {
  Vec3 r = applyLinear(p);
  for (int i = 0; i < 3; ++i) r[i] += t[i];
  return r;
}

Affine Affine::then(const Affine &o) const {
  Affine r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = o.m[i][0] * m[0][j] + o.m[i][1] * m[1][j] + o.m[i][2] * m[2][j];
  r.t = o.apply(t);
  return r;
}

double Affine::det() const { return mat3Det(m); }

Affine Affine::inverse() const {
  Affine r;
  mat3Inverse(m, r.m);  // frames never have det 0: scale factors of 0 are rejected
  Vec3 nt = r.applyLinear(t);
  r.t = {-nt[0], -nt[1], -nt[2]};
  return r;
}

bool Affine::linearIdentity() const {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (m[i][j] != (i == j ? 1.0 : 0.0)) return false;
  return true;
}

Affine Affine::rotation(Vec3 u, double degrees, const Vec3 &centre) {
  double n = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  for (double &x : u) x /= n;
  double s, c;
  sinCosDegrees(degrees, s, c);
  double k = 1 - c;
  Affine a;  // Rodrigues: counter-clockwise seen from the tip of u
  a.m[0][0] = c + u[0] * u[0] * k, a.m[0][1] = u[0] * u[1] * k - u[2] * s, a.m[0][2] = u[0] * u[2] * k + u[1] * s;
  a.m[1][0] = u[1] * u[0] * k + u[2] * s, a.m[1][1] = c + u[1] * u[1] * k, a.m[1][2] = u[1] * u[2] * k - u[0] * s;
  a.m[2][0] = u[2] * u[0] * k - u[1] * s, a.m[2][1] = u[2] * u[1] * k + u[0] * s, a.m[2][2] = c + u[2] * u[2] * k;
  Vec3 rc = a.applyLinear(centre);
  for (int i = 0; i < 3; ++i) a.t[i] = centre[i] - rc[i];
  return a;
}

Affine Affine::scaling(const Vec3 &f, const Vec3 &centre) {
  Affine a;
  for (int i = 0; i < 3; ++i) {
    a.m[i][i] = f[i];
    a.t[i] = centre[i] - f[i] * centre[i];
  }
  return a;
}

void ProgrammableFrame::update() {
  copy = Affine{};
  if (copyOn && copyAngle != 0) copy = Affine::rotation(copyAxis, copyIndex * copyAngle, copyCentre);
  if (copyOn)
    for (int i = 0; i < 3; ++i) copy.t[i] += copyIndex * copyShift[i];
  Affine c = copy;
  Vec3 mirror{1, 1, 1};
  for (int i = 0; i < 3; ++i)
    if (mirrorAxes[i]) mirror[i] = -1;
  // Scale, then mirror, then rotate (Heidenhain's 26/11, 8, 10: digest seed002a §4.8's model;
  // ISO never has two kinds at once).
  if (scaleOn) c = c.then(Affine::scaling(scaleFactors, scaleCentre));
  c = c.then(Affine::scaling(mirror, mirrorAt));
  if (rotationLevels == 2) c = c.then(rotation[1]);
  if (rotationLevels >= 1) c = c.then(rotation[0]);
  linear = !c.linearIdentity() || copyOn || tiltOn;  // a copy's shift is in the composite, not in local
  for (int i = 0; i < 3; ++i) c.t[i] += local[i];
  if (tiltOn) c = c.then(tilt);
  composite = c;
  inverseComposite = c.inverse();
}

bool ProgrammableFrame::similar() const {
  const auto &m = composite.m;
  double col[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) col[j][i] = m[i][j];
  auto dot = [&](int a, int b) { return col[a][0] * col[b][0] + col[a][1] * col[b][1] + col[a][2] * col[b][2]; };
  double k = dot(0, 0), tol = 1e-12 * k;
  return std::fabs(dot(1, 1) - k) <= tol && std::fabs(dot(2, 2) - k) <= tol && std::fabs(dot(0, 1)) <= tol &&
         std::fabs(dot(0, 2)) <= tol && std::fabs(dot(1, 2)) <= tol;
}

AxisVec ProgrammableFrame::out(const AxisVec &p) const {
  AxisVec r = p;
  Vec3 x = composite.apply({p[0], p[1], p[2]});
  for (int i = 0; i < 3; ++i) r[i] = x[i];
  for (int i = 3; i < kAxes; ++i) r[i] += local[i];
  return r;
}

AxisVec ProgrammableFrame::in(const AxisVec &s) const {
  AxisVec r = s;
  Vec3 x = inverseComposite.apply({s[0], s[1], s[2]});
  for (int i = 0; i < 3; ++i) r[i] = x[i];
  for (int i = 3; i < kAxes; ++i) r[i] -= local[i];
  return r;
}

}  // namespace ncc
