// Kinematic transformations (SIN-TRF-02/03/04, docs/SINUMERIK.md "Transformations"): TRANSMIT,
// TRANSMIT(n), TRACYL(d), TRACYL(d, n), TRACYL(d, n, k) and TRAFOOF are lowered to the library
// entries trf.TRANSMIT, trf.TRACYL and trf.TRAFOOF (docs/IR.md §5.8), which the executor runs
// (runtime/ExecutorTransform.cpp, the core every dialect shares). Each stands alone in its block.
#include "frontend/sinumerik/Parser.h"

#include <fmt/format.h>

namespace ncc::sin {

using ir::Expr;
using ir::Op;
using ir::OpKind;

bool BlockParser::transformation(const std::string &kw) {
  const Token &at = tok();
  SourceLoc l = loc(at);
  if (!words_.empty() || !gcodes_.empty() || !pre_.empty())
    return fail(at, fmt::format("'{}' must stand alone in its block", kw));
  ++i_;
  Op c(OpKind::Cycle, l);
  c.set("entry", Expr::string("trf." + kw, l));
  if (kw == "TRACYL" && !tok().is("("))
    return fail(at, "TRACYL needs the reference diameter: TRACYL(<d>), TRACYL(<d>, <n>) or TRACYL(<d>, <n>, <k>)",
                "missing-word");
  if (kw == "TRAFOOF" && tok().is("(")) return fail(tok(), "TRAFOOF takes no arguments");
  static const std::vector<std::string> kTransmit = {"N"}, kTracyl = {"D", "N", "K"};
  if (!argumentList(kw, kw == "TRACYL" ? kTracyl : kTransmit, "a.", c)) return false;
  if (kw == "TRACYL" && !c.get("a.D"))
    return fail(at, "TRACYL needs the reference diameter <d> as its first argument", "missing-word");
  if (!atEnd()) return fail(tok(), fmt::format("'{}' must stand alone in its block", kw));
  post_.push_back(std::move(c));
  return true;
}

}  // namespace ncc::sin
