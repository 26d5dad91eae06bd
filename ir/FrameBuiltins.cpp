#include "ir/FrameBuiltins.h"
#include "ir/Strings.h"

#include <fmt/format.h>

#include <cmath>

namespace ncc {

namespace {
struct FrameArgs {
  ValuePool &pool;
  const double *a;
  unsigned n;
  std::string &error;
  const char *fn;

  bool fail(std::string msg) {
    error = fmt::format("'{}': {}", fn, msg);
    return false;
  }
  bool axis(unsigned i, int &out) {
    if (!isString(a[i])) return fail(fmt::format("argument {} must be an axis name", i + 1));
    std::string_view s = pool.text(a[i]);
    if (!frameAxis(s, out)) return fail(fmt::format("axis '{}' is not one of X Y Z A B C", s));
    return true;
  }
  bool number(unsigned i, double &out) {
    if (isHandle(a[i])) return fail(fmt::format("argument {} must be a number", i + 1));
    out = num(a[i]);
    return true;
  }
  bool frame(unsigned i, const FrameValue *&out) {
    if (!isFrame(a[i])) return fail(fmt::format("argument {} must be a frame", i + 1));
    out = &pool.frames.get(a[i]);
    return true;
  }
  bool ret(const FrameValue &f, double &out) { return pool.frames.intern(f, out, error); }
  // (axis, value) pairs: `set` stores one pair into the parts.
  template <class Set>
  bool pairs(FrameParts &p, Set set) {
    if (n % 2) return fail("takes axis, value pairs");
    bool seen[kFrameAxes] = {};
    for (unsigned i = 0; i < n; i += 2) {
      int ax;
      double v;
      if (!axis(i, ax) || !number(i + 1, v)) return false;
      if (seen[ax]) return fail(fmt::format("axis {} is given twice", frameAxisName(ax)));
      seen[ax] = true;
      if (!set(p, ax, v)) return false;
    }
    return true;
  }
  bool scale(FrameParts &p, int ax, double v) {
    if (v == 0 || !std::isfinite(v)) return fail(fmt::format("scale factor of {} must not be 0", frameAxisName(ax)));
    p.sc[ax] = std::fabs(v);
    if (v < 0) p.mi[ax] = !p.mi[ax];
    return true;
  }
};
}  // namespace

bool frameCtrans(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error) {
  FrameArgs a{pool, args, n, error, "CTRANS"};
  FrameParts p;
  return a.pairs(p, [](FrameParts &p, int ax, double v) { return p.tr[ax] = v, true; }) && a.ret(frameCompose(p), out);
}

bool frameCfine(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error) {
  FrameArgs a{pool, args, n, error, "CFINE"};
  FrameParts p;
  return a.pairs(p, [](FrameParts &p, int ax, double v) { return p.fi[ax] = v, true; }) && a.ret(frameCompose(p), out);
}

bool frameCrot(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error) {
  FrameArgs a{pool, args, n, error, "CROT"};
  FrameParts p;
  return a.pairs(p,
                 [&](FrameParts &p, int ax, double v) {
                   if (ax >= 3) return a.fail(fmt::format("a rotation about {} (frames rotate about X Y Z)", frameAxisName(ax)));
                   return p.rt[ax] = v, true;
                 }) &&
         a.ret(frameCompose(p), out);
}

bool frameCrots(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error) {
  FrameArgs a{pool, args, n, error, "CROTS"};
  FrameParts p;
  bool given[3] = {};
  if (!a.pairs(p, [&](FrameParts &p, int ax, double v) {
        if (ax >= 3) return a.fail(fmt::format("a solid angle at {} (frames rotate about X Y Z)", frameAxisName(ax)));
        return given[ax] = true, p.rt[ax] = v, true;
      }))
    return false;
  FrameValue f;
  std::string err;
  if (!frameSolidRotation(given, p.rt, f.L, err)) return a.fail(err);
  return a.ret(f, out);
}

bool frameCscale(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error) {
  FrameArgs a{pool, args, n, error, "CSCALE"};
  FrameParts p;
  return a.pairs(p, [&](FrameParts &p, int ax, double v) { return a.scale(p, ax, v); }) && a.ret(frameCompose(p), out);
}

bool frameCmirror(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error) {
  FrameArgs a{pool, args, n, error, "CMIRROR"};
  FrameParts p;
  for (unsigned i = 0; i < n; ++i) {
    int ax;
    if (!a.axis(i, ax)) return false;
    if (p.mi[ax]) return a.fail(fmt::format("axis {} is given twice", frameAxisName(ax)));
    p.mi[ax] = true;
  }
  return a.ret(frameCompose(p), out);
}

bool frameInvframe(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error) {
  FrameArgs a{pool, args, n, error, "INVFRAME"};
  const FrameValue *f;
  return a.frame(0, f) && a.ret(frameInverse(*f), out);
}

bool frameChainFn(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error) {
  FrameArgs a{pool, args, n, error, "FRAME_CHAIN"};
  const FrameValue *x, *y;
  if (!a.frame(0, x) || !a.frame(1, y)) return false;
  FrameValue r = frameChain(*x, *y);  // before interning: the pool may grow and move x, y
  return a.ret(r, out);
}

// The component and axis arguments of FRAME_GET/FRAME_SET, and the decomposition RT SC MI need.
static bool component(FrameArgs &a, int &ax, FrameComp &c) {
  if (!a.axis(1, ax)) return false;
  std::string_view s = isString(a.a[2]) ? a.pool.text(a.a[2]) : std::string_view();
  if (!frameComp(s, c)) return a.fail("argument 3 must be a frame component TR FI RT SC MI");
  if (c == FrameComp::RT && ax >= 3)
    return a.fail(fmt::format("RT is a rotation about X Y or Z, not about {}", frameAxisName(ax)));
  return true;
}

static bool parts(FrameArgs &a, const FrameValue &f, FrameComp c, FrameParts &p) {
  if (c == FrameComp::TR || c == FrameComp::FI) {  // always exact: no decomposition needed
    for (int i = 0; i < kFrameAxes; ++i) p.tr[i] = f.coarse[i], p.fi[i] = f.fine[i];
    return true;
  }
  std::string err;
  if (!frameDecompose(f, p, err)) return a.fail(err);
  return true;
}

bool frameGet(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error) {
  FrameArgs a{pool, args, n, error, "FRAME_GET"};
  const FrameValue *f;
  int ax;
  FrameComp c;
  FrameParts p;
  if (!a.frame(0, f) || !component(a, ax, c) || !parts(a, *f, c, p)) return false;
  switch (c) {
  case FrameComp::TR: out = p.tr[ax]; break;
  case FrameComp::FI: out = p.fi[ax]; break;
  case FrameComp::RT: out = p.rt[ax]; break;
  case FrameComp::SC: out = p.sc[ax]; break;
  case FrameComp::MI: out = p.mi[ax] ? 1.0 : 0.0; break;
  }
  return true;
}

bool frameSet(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error) {
  FrameArgs a{pool, args, n, error, "FRAME_SET"};
  const FrameValue *f;
  int ax;
  FrameComp c;
  double v;
  if (!a.frame(0, f) || !component(a, ax, c) || !a.number(3, v)) return false;
  FrameValue r = *f;
  if (c == FrameComp::TR || c == FrameComp::FI) {  // the offset alone: the matrix stays as it is
    (c == FrameComp::TR ? r.coarse : r.fine)[ax] = v;
    return a.ret(r, out);
  }
  FrameParts p;
  if (!parts(a, *f, c, p)) return false;
  switch (c) {
  case FrameComp::RT: p.rt[ax] = v; break;
  case FrameComp::SC:  // the factor's size; a negative one toggles the mirror (as CSCALE)
    if (!a.scale(p, ax, v)) return false;
    break;
  case FrameComp::MI: p.mi[ax] = truthy(v); break;
  default: break;
  }
  return a.ret(frameCompose(p), out);
}

}  // namespace ncc
