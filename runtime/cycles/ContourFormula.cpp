#include "runtime/cycles/ContourFormula.h"

#include "runtime/cycles/ClipperPaths.h"
#include "runtime/cycles/Region.h"

#include <fmt/format.h>

#include <map>

namespace ncc {

bool buildFormula(const std::vector<FormulaStep> &steps, ContourFormula &out, std::string &err) {
  out = {};
  std::map<int, int> named;  // QC number -> node
  std::vector<int> stack;
  for (const FormulaStep &s : steps) {
    switch (s.kind) {
    case FormulaStep::Declare:
      out.nodes.push_back({0, s.sub, -1, -1});
      named[s.n] = (int)out.nodes.size() - 1;
      break;
    case FormulaStep::Push: {
      auto it = named.find(s.n);
      if (it == named.end()) return err = fmt::format("QC{} is used in a contour formula before it is declared", s.n), false;
      stack.push_back(it->second);
      break;
    }
    case FormulaStep::Apply: {
      if (stack.size() < 2 || s.n < (int)FormulaOp::Union || s.n > (int)FormulaOp::Difference)
        return err = "a contour formula's operator needs two operands", false;
      const int right = stack.back();
      stack.pop_back();
      out.nodes.push_back({s.n, -1, stack.back(), right});
      stack.back() = (int)out.nodes.size() - 1;
      break;
    }
    case FormulaStep::Store:
      if (stack.size() != 1) return err = "a contour formula must reduce to one contour", false;
      named[s.n] = out.root = stack.back();
      stack.clear();
      break;
    }
  }
  if (!stack.empty()) return err = "a contour formula was not assigned to a QC", false;
  if (out.root < 0) return err = "the contour program has no contour formula (QCn = …)", false;
  return true;
}

namespace {
bool inside(const ContourFormula &f, int k, const std::function<bool(int)> &in) {
  const FormulaNode &n = f.nodes[k];
  if (n.op == 0) return in(n.sub);
  const bool a = inside(f, n.left, in), b = inside(f, n.right, in);
  switch ((FormulaOp)n.op) {
  case FormulaOp::Union: return a || b;
  case FormulaOp::Intersection: return a && b;
  case FormulaOp::Xor: return a != b;
  case FormulaOp::Difference: return a && !b;
  }
  return false;
}

// The polygons of node k. A capture's arcs are sampled on the safe side of the result: inside
// where the operand adds to the region (`grow`), outside where it takes away from it (the right
// side of a difference; `^` is (A | B) \ (A & B), each operand both ways).
struct AreaEval {
  const ContourFormula &f;
  const std::vector<SubContour> &subs;
  double tol;
  std::string &err;
  bool eval(int k, bool grow, ClipperLib::Paths &out) {
    const FormulaNode &n = f.nodes[k];
    if (n.op == 0) {
      Polygon p;
      if (!regionPolygon(subs[n.sub].loop, !grow, tol, p, err)) return false;
      out = {toPath(p)};
      if (!ClipperLib::Orientation(out[0])) ClipperLib::ReversePath(out[0]);  // an island's comes clockwise
      return true;
    }
    ClipperLib::Paths a, b;
    switch ((FormulaOp)n.op) {
    case FormulaOp::Union:
    case FormulaOp::Intersection:
      if (!eval(n.left, grow, a) || !eval(n.right, grow, b)) return false;
      out = clipPaths(n.op == (int)FormulaOp::Union ? ClipperLib::ctUnion : ClipperLib::ctIntersection, a, b);
      return true;
    case FormulaOp::Difference:
      if (!eval(n.left, grow, a) || !eval(n.right, !grow, b)) return false;
      out = clipPaths(ClipperLib::ctDifference, a, b);
      return true;
    case FormulaOp::Xor: {
      ClipperLib::Paths c, d;
      if (!eval(n.left, grow, a) || !eval(n.right, grow, b) || !eval(n.left, !grow, c) || !eval(n.right, !grow, d))
        return false;
      out = clipPaths(ClipperLib::ctDifference, clipPaths(ClipperLib::ctUnion, a, b), clipPaths(ClipperLib::ctIntersection, c, d));
      return true;
    }
    }
    return err = "unknown contour formula operator", false;
  }
};
}  // namespace

bool formulaContains(const ContourFormula &f, const std::function<bool(int sub)> &in) {
  return f.root >= 0 && inside(f, f.root, in);
}

bool formulaOperand(RegionLoop loop, double tol, SubContour &out, std::string &err) {
  if (!closedLoop(loop, err) || !regionPolygon(loop, false, tol, out.poly, err)) return false;
  out.pocket = true;
  out.start = loop.start;
  out.loop = std::move(loop);
  return true;
}

bool formulaArea(const PocketRegion &region, double tol, std::vector<Polygon> &area, std::string &err) {
  ContourFormula f;
  if (!buildFormula(region.formula, f, err)) return false;
  ClipperLib::Paths a;
  if (!AreaEval{f, region.subs, tol, err}.eval(f.root, true, a)) return false;
  area.clear();
  for (auto &p : a) area.push_back(fromPath(p));
  if (area.empty()) return err = "the contour formula's region encloses no area", false;
  return true;
}

}  // namespace ncc
