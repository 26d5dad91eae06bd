// Heidenhain contour formulas (docs/HEIDENHAIN.md "Contour formulas", manual L11776-L12416): a
// region combined from closed sub-contours with union `|`, intersection `&`, union without the
// intersection `^` and difference `\`. The front end lowers SEL CONTOUR's program (DECLARE CONTOUR
// QCn = …, QCm = formula) and CONTOUR DEF to steps in postfix order (docs/IR.md §5.6): each
// captured operand declares its number, formulas push, apply and store. The formula is kept as a
// tree over the operands' captures so that each consumer evaluates it its own way: the region
// pockets with Clipper polygons (Region.h formulaArea), side finishing with the exact elements
// (ArcRegion.h). This header stays free of both so that either can include it.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace ncc {

enum class FormulaOp : int { Union = 1, Intersection = 2, Xor = 3, Difference = 4 };

struct FormulaStep {
  enum Kind : int { Declare, Push, Apply, Store } kind = Push;
  int n = 0;  // the QC number (Declare, Push, Store) or the FormulaOp (Apply)
  int sub = -1;  // Declare: the capture's index among the region's sub-contours
};

// A node: a leaf (op 0) names a capture; otherwise op combines left and right.
struct FormulaNode {
  int op = 0;
  int sub = -1;
  int left = -1, right = -1;
};
struct ContourFormula {
  std::vector<FormulaNode> nodes;
  int root = -1;  // the last formula stored (-1: none)
};

// The tree of the steps: Push takes the latest Declare or Store of its number. False with a
// message for a number pushed before it is declared, an operator without two operands, a
// formula left unstored or no formula at all.
bool buildFormula(const std::vector<FormulaStep> &steps, ContourFormula &out, std::string &err);

// Whether a point lies in the formula's region, given whether it lies inside each capture.
bool formulaContains(const ContourFormula &f, const std::function<bool(int sub)> &inside);

}  // namespace ncc
