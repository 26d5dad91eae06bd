// FK free contour programming in the front end (Fk.cpp): the chain of FK blocks whose geometry
// is being solved, and the position known when the program is read that the chain starts from.
#pragma once
#include "frontend/heidenhain/FkSolver.h"
#include "frontend/heidenhain/Parser.h"

#include <memory>
#include <optional>
#include <vector>

namespace ncc::hei {

// One FK element waiting to be lowered: its block (the lowering is located there) and the words
// that are lowered around its move (feed, M functions, compensation).
struct FkPending {
  Block *block;
  PathWords words;
  bool arc;
};

struct FkChain {
  std::optional<fk::Pt> pole;                // FPOL
  std::optional<fk::Pt> here, heading;       // where the contour stands, when known statically
  std::vector<fk::Hyp> hyps;                 // the ways the chain may go (empty: no chain)
  std::vector<std::unique_ptr<FkPending>> elems;
  size_t lowered = 0;                        // elements handed on to the body
};

}  // namespace ncc::hei
