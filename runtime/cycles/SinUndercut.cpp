// Sinumerik undercuts CYCLE940 (SIN-CYC-26, seed000c 19.1.41): DIN 509 forms E and F, the DIN 76
// thread undercuts A and B (outside), and the free thread undercut T, at a shoulder of a shaft
// or a bore. The manual lists the parameters and the table selections (_PITI) only; the
// dimensions are DIN 509's and DIN 76-1's (the tables below), the profile and the passes ncc's
// model, docs/CYCLES.md "Sinumerik undercuts". ZX plane, program coordinates, X a radius.
#include "runtime/cycles/Entry.h"
#include "runtime/cycles/TurnPath.h"

#include <cmath>
#include <fmt/format.h>

namespace ncc {

using namespace entry;

namespace {

constexpr double kEps = 1e-9;
constexpr double kMaxPasses = 10000;

// DIN 509 (2006, table 1) undercuts of forms E and F in the order of _PITI (radius x depth):
// the radius r, the depth t1 into the cylinder, the width f along it (from the face), the
// depth t2 into the face (form F). 0.1 x 0.1 is the 1998 edition's smallest row.
struct Din509 {
  double r, t1, f, t2;
};
constexpr Din509 kDin509[] = {
    {0.6, 0.3, 2.5, 0.2}, {1.0, 0.4, 4.0, 0.3}, {1.0, 0.2, 2.5, 0.1}, {1.6, 0.3, 4.0, 0.2}, {2.5, 0.4, 5.0, 0.3},
    {4.0, 0.5, 7.0, 0.3}, {0.4, 0.2, 2.0, 0.1}, {0.6, 0.2, 2.0, 0.1}, {0.1, 0.1, 0.5, 0.1}, {0.2, 0.1, 1.0, 0.1},
};
constexpr double kDin509Run = 15;   // degrees: the run-out to the cylinder, from the axis
constexpr double kDin509Face = 8;   // degrees: form F's flank into the face, from the radial

// DIN 76-1 (table 1) thread undercuts of external metric threads in the order of _PITI: the
// pitch P, d - dg (the undercut's diameter below the thread's), the radius r at the shoulder,
// and the length g2 (at the thread's diameter) of the normal form A and the short form B.
struct Din76 {
  double pitch, dgBelow, r, g2a, g2b;
};
constexpr Din76 kDin76[] = {
    {0.20, 0.3, 0.10, 0.70, 0.50}, {0.25, 0.4, 0.12, 0.90, 0.60}, {0.30, 0.5, 0.16, 1.05, 0.75},
    {0.35, 0.6, 0.16, 1.20, 0.90}, {0.40, 0.7, 0.20, 1.40, 1.00}, {0.45, 0.7, 0.20, 1.60, 1.10},
    {0.50, 0.8, 0.20, 1.75, 1.25}, {0.60, 1.0, 0.40, 2.10, 1.50}, {0.70, 1.1, 0.40, 2.45, 1.75},
    {0.75, 1.2, 0.40, 2.60, 1.90}, {0.80, 1.3, 0.40, 2.80, 2.00}, {1.00, 1.6, 0.60, 3.50, 2.50},
    {1.25, 2.0, 0.60, 4.40, 3.20}, {1.50, 2.3, 0.80, 5.20, 3.80}, {1.75, 2.6, 1.00, 6.10, 4.30},
    {2.00, 3.0, 1.00, 7.00, 5.00}, {2.50, 3.6, 1.20, 8.70, 6.30}, {3.00, 4.4, 1.60, 10.50, 7.50},
    {3.50, 5.0, 1.60, 12.00, 9.00}, {4.00, 5.7, 2.00, 14.00, 10.00}, {4.50, 6.4, 2.50, 16.00, 11.00},
    {5.00, 7.0, 2.50, 17.50, 12.50}, {5.50, 7.7, 3.20, 19.00, 14.00}, {6.00, 8.3, 3.20, 21.00, 15.00},
};

double tanDeg(double deg) { return std::tan(deg * M_PI / 180); }

// The undercut's profile in its frame (u from the shoulder's face along the cylinder, v the
// depth below the cylinder's surface X0): from the run-out's outer end down to the bottom, along
// it, round the corner at the face and up the face, as corner points with their rounds.
struct Profile {
  std::vector<Pt2> pts;
  std::vector<Round> rounds;
  void add(Pt2 p, Round r = {}) { pts.push_back(p), rounds.push_back(r); }
};

// The run-out through the point (u, v) rising at `angle` degrees to the axis, at depth `at`.
double runOutU(Pt2 foot, double angle, double at) {
  return angle >= 90 ? foot.a : foot.a + (foot.b - at) / tanDeg(angle);
}

// A thread undercut (DIN 76 A/B or T): the face at u = face, the bottom at depth h, its foot on
// the run-out at uFoot (rounded by rFoot), the face corner rounded by rFace, the run-out at
// `angle`; from `top` above the surface down, up the face to `exit`.
Profile threadProfile(double face, double h, double uFoot, double angle, Round rFoot, Round rFace, double top,
                      double exit) {
  Profile p;
  p.add({runOutU({uFoot, h}, angle, top), top});
  p.add({uFoot, h}, rFoot);
  p.add({face, h}, rFace);
  p.add({face, exit});
  return p;
}

// CYCLE940(_SPD, _SPL, _FORM, _LAGE, _SDIS, _FFP, _VARI, _EPD, _EPL, _R1, _R2, _STA, _VRT, _MID,
// _FAL, _FALX, _FALZ, _PITI, _PTAB, _PTABA, _DMODE, _AMODE)
bool sinCycle940(const CycleArgs &a, const CycleContext &ctx, std::vector<CycleStep> &out, std::string &err) {
  if (sinPlane(a, ctx) != 1) return unsupported(err, "undercuts outside the turning plane G18 are not supported");
  for (const char *k : {"_SPD", "_SPL"})
    if (!a.has(k)) return fail(err, std::string(k) + " is required");
  auto form = a.text.find("_FORM");
  if (form == a.text.end() || form->second.size() != 1)
    return fail(err, "_FORM must be one letter: \"A\", \"B\", \"C\", \"D\" (DIN 76), \"E\", \"F\" (DIN 509) or \"T\" (free)");
  const char kind = form->second[0];
  if (kind == 'C' || kind == 'D')
    return unsupported(err, fmt::format("_FORM \"{}\": the inside DIN 76 undercuts are not supported (their run-out "
                                        "must reach the bore, whose diameter the cycle is not given)",
                                        kind));
  if (std::string("ABEFT").find(kind) == std::string::npos)
    return fail(err, fmt::format("_FORM \"{}\" is not an undercut form: A-D (DIN 76), E, F (DIN 509) or T (free; upper case)",
                                 form->second));
  const int lage = (int)a.get("_LAGE");
  if (lage != a.get("_LAGE") || lage < 0 || lage > 3)
    return fail(err, "_LAGE must be 0 (outside, +Z), 1 (outside, -Z), 2 (inside, +Z) or 3 (inside, -Z)");
  const double amode = a.get("_AMODE");
  for (int d = 1; d <= 4; ++d)
    if (digit(amode, d) > 1) return fail(err, fmt::format("_AMODE digit {} must be 0 or 1", d));
  if (kind == 'A' || kind == 'B') {
    if (lage > 1) return fail(err, fmt::format("_FORM \"{}\" is an outside undercut: _LAGE must be 0 or 1", kind));
  }
  // The frame: u from the face (Z0) away from the shoulder, which lies on the +Z side for
  // _LAGE 0 and 2; v from the surface (X0) into the material.
  GrooveFrame f;
  f.su = lage % 2 == 0 ? -1 : 1;
  f.sv = lage < 2 ? -1 : 1;
  f.w0 = a.get("_SPL");
  f.d0 = a.get("_SPD") / 2;
  // A depth on the X axis from an absolute diameter or (inc) a radius outwards from X0.
  auto depthOf = [&](double value, bool inc) { return inc ? -value : f.sv * (value / 2 - f.d0); };
  double sdis = a.get("_SDIS");
  if (sdis < 0) return fail(err, "_SDIS (safety clearance) must not be negative");
  if (sdis == 0) sdis = 1;  // [model] as CYCLE930 and CYCLE951: 1 mm
  // _FFP is mm/rev (the manual): as it stands under G95, times the spindle speed under G94.
  double feed = std::fabs(a.get("_FFP"));
  if (!ctx.feedPerRev && feed > 0) {
    if (!(ctx.speed > 0)) return fail(err, "_FFP is a feed per revolution: under G94 it needs a spindle speed S");
    feed *= ctx.speed;
  }
  const double vx = depthOf(a.get("_VRT"), digit(amode, 3) == 1);
  const int piti = (int)a.get("_PITI");
  if (piti != a.get("_PITI") || piti < 0) return fail(err, "_PITI must be a table index 0 or more");
  bool rough = false, finish = true;
  Profile fin;  // the finished profile; `slope`: the run-out's angle; the roughing profile below
  double angle = 0, h = 0, top = -sdis;
  Round rFoot, rFace;
  double uFoot = 0;
  if (kind == 'E' || kind == 'F') {
    if (piti > 9) return fail(err, fmt::format("_PITI {} is not a DIN 509 size (0-9: radius x depth)", piti));
    const Din509 &d = kDin509[piti];
    // Allowances for grinding: the cylinder (X1 _EPD) and, form F, the face (Z1 _EPL) stand
    // proud of the finished surfaces the table measures from.
    const double ux = !a.has("_EPD") ? 0 : digit(amode, 1) == 1 ? a.get("_EPD") : -depthOf(a.get("_EPD"), false);
    const double uz = kind != 'F' || !a.has("_EPL") ? 0
                      : digit(amode, 2) == 1 ? a.get("_EPL") : f.su * (a.get("_EPL") - f.w0);
    if (ux < 0 || uz < 0) return fail(err, "the allowances _EPD (X1) and _EPL (Z1) must lie outside the finished surfaces");
    angle = kDin509Run, h = d.t1, top = -ux - sdis;
    const Pt2 foot{d.f - d.t1 / tanDeg(angle), d.t1};
    fin.add({runOutU(foot, angle, top), top});
    fin.add(foot);
    double faceTop = d.t1 - d.r;  // where the pass reaches the face
    if (kind == 'E') {
      fin.add({0, d.t1}, Round{d.r, false});
      fin.add({0, vx});
    } else {
      // The flank into the face leans 8 degrees; its corner with the bottom, rounded by r, puts
      // the deepest point t2 behind the face.
      const double s = std::sin(kDin509Face * M_PI / 180), c = std::cos(kDin509Face * M_PI / 180);
      const Pt2 k{d.r - d.t2 - d.r * (1 + s) / c, d.t1};
      const double vFace = d.t1 - (uz - k.a) * c / s;  // where the flank meets the (unground) face
      fin.add(k, Round{d.r, false});
      fin.add({uz, vFace});
      fin.add({uz, vx});
      faceTop = vFace;
    }
    if (!(vx < faceTop - kEps))
      return fail(err, "_VRT (VX, where the pass leaves along the face) does not lie above the undercut's face");
  } else {
    const double vari = a.get("_VARI");
    const int machining = digit(vari, 1), strategy = digit(vari, 2);
    if (vari != std::floor(vari) || vari < 0 || vari >= 100 || machining < 1 || machining > 3 || strategy > 1)
      return fail(err, "_VARI must be 1-3 (roughing, finishing, both) with 2nd digit 0 (parallel to the contour) or 1 (longitudinal)");
    rough = machining != 2, finish = machining != 1;
    if (rough && strategy == 1)
      return unsupported(err, "_VARI 2nd digit 1: longitudinal roughing of an undercut is not supported (give 0, parallel to the contour)");
    angle = a.get("_STA");
    if (!(angle > 0 && angle <= 90)) return fail(err, "_STA (the insertion angle) must lie in 0 < angle <= 90 degrees");
    double width = 0;
    if (kind == 'T') {
      h = depthOf(a.get("_EPD"), digit(amode, 1) == 1);
      width = digit(amode, 2) == 1 ? a.get("_EPL") : f.su * (a.get("_EPL") - f.w0);
      rFoot = {a.get("_R1"), false}, rFace = {a.get("_R2"), false};
      if (rFoot.size < 0 || rFace.size < 0) return fail(err, "the radii _R1 and _R2 must not be negative");
      if (!(h > kEps)) return fail(err, "_EPD (X1, the undercut's depth) must lie inside the material");
      if (!(width > kEps)) return fail(err, "_EPL (Z1, the undercut's width) must lie away from the shoulder");
    } else {
      if (piti >= (int)(sizeof kDin76 / sizeof kDin76[0]))
        return fail(err, fmt::format("_PITI {} is not a DIN 76 pitch (0-23: 0.2-6 mm)", piti));
      const Din76 &d = kDin76[piti];
      h = d.dgBelow / 2, width = kind == 'A' ? d.g2a : d.g2b;
      rFace = {d.r, false};
    }
    uFoot = width - h / tanDeg(angle);
    if (angle >= 90) uFoot = width;
    if (!(uFoot > kEps)) return fail(err, "the undercut's run-out at _STA reaches past the face: it is too short for its depth");
    if (finish) {
      fin = threadProfile(0, h, uFoot, angle, rFoot, rFace, top, vx);
      if (!(vx < -kEps)) return fail(err, "_VRT (VX, where the finishing pass leaves along the face) must lie above the surface X0");
    }
  }
  if (ctx.toolRadius > 0)
    return unsupported(err, "undercuts with a tool nose radius are not supported: ncc traces the tool's sharp "
                            "point along the profile (give the tool radius 0)");
  std::vector<ContourElem> moves;  // in the frame
  auto pass = [&](const Profile &p, double lift, double leaveTo) {
    std::vector<ContourElem> elems;
    Profile q = p;
    for (Pt2 &pt : q.pts) pt.b -= lift;
    q.pts[0] = {runOutU(q.pts[1], angle, top), top};  // the lifted run-out from the safety level
    q.pts.back().b = leaveTo;
    if (!roundedPath(q.pts, q.rounds, elems, err)) return false;
    ContourElem e;
    e.kind = ContourKind::Rapid, e.end = q.pts[0];
    moves.push_back(e);
    moves.insert(moves.end(), elems.begin(), elems.end());
    e.end = {q.pts.back().a + sdis, leaveTo};  // off the face
    moves.push_back(e);
    return true;
  };
  if (rough) {
    // Passes parallel to the contour: the profile less the allowances lifted off the bottom in
    // equal steps of at most _MID, each from the run-out's extension down and up the face to
    // the safety level.
    double ux = 0, uz = 0;
    if (digit(amode, 4) == 1) {
      ux = a.get("_FALX"), uz = a.get("_FALZ");
    } else if (a.get("_FAL") != 0) {
      return unsupported(err, fmt::format("_FAL {:g}: an allowance parallel to the contour is not supported: give "
                                          "_FALX/_FALZ (_AMODE 4th digit 1)",
                                          a.get("_FAL")));
    }
    if (ux < 0 || uz < 0) return fail(err, "the finishing allowances _FALX and _FALZ must not be negative");
    const double depth = h - ux, mid = a.get("_MID");
    if (!(depth > kEps)) return fail(err, "the finishing allowance leaves nothing to rough");
    if (!(mid > 0)) return fail(err, "_MID (D, the depth infeed) must be greater than 0");
    if (depth / mid > kMaxPasses) return fail(err, "_MID (D, the depth infeed) is too small for the undercut");
    const int n = (int)std::ceil(depth / mid - 1e-9);
    const Profile r = threadProfile(uz, depth, uFoot - uz, angle, rFoot, rFace, top, -sdis);
    for (int k = n - 1; k >= 0; --k)
      if (!pass(r, depth * k / n, -sdis)) return false;
  }
  if (finish && !pass(fin, 0, fin.pts.back().b)) return false;
  const Pt2 here{ctx.position[2], ctx.position[0]};
  std::vector<ContourElem> plane;
  f.approach(here, moves.front().end, plane);
  for (const ContourElem &m : moves) plane.push_back(f.toPlane(m, 0));
  contourSteps(plane, here, ctx.position[1], feed, 0, 0, out);
  return true;
}

const CycleDef kEntries[] = {
    {"sin.CYCLE940",
     "_SPD _SPL _FORM _LAGE _SDIS _FFP _VARI _EPD _EPL _R1 _R2 _STA _VRT _MID _FAL _FALX _FALZ _PITI _PTAB _PTABA "
     "_DMODE _AMODE",
     "Sinumerik undercut", sinCycle940, nullptr, nullptr, "_FORM ~_PTAB ~_PTABA"},
};

}  // namespace

void addSinUndercutEntries(std::vector<CycleDef> &out) {
  for (const CycleDef &d : kEntries) out.push_back(d);
}

}  // namespace ncc
