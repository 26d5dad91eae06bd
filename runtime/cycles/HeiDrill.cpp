#include "runtime/cycles/HeiDrill.h"
#include "runtime/cycles/Hole.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ncc {

bool peckDrill(Mill &m, const PeckPlan &p, std::string &err) {
  const char *tooSmall = "the infeed (Q202, Q205 or Q257) is too small: more than a million infeeds";
  if (p.chipEvery > 0 && (p.depth - p.start) / p.chipEvery > kMaxPecks) return err = tooSmall, false;
  // The infeeds' ends first: the advance distances spread over the re-entries between them.
  std::vector<double> ends;
  for (double at = p.start, step = p.infeed; at < p.depth;) {
    at = step > 0 ? std::min(at + step, p.depth) : p.depth;
    ends.push_back(at);
    // Smaller by the decrement down to the minimum; without a minimum never down to nothing.
    if (p.decrement > 0 && std::max(step - p.decrement, p.minInfeed) > 0) step = std::max(step - p.decrement, p.minInfeed);
    if (ends.size() > kMaxPecks) return err = tooSmall, false;
  }
  const size_t reentries = ends.size() - 1;
  const PlanePoint centre = m.here();
  double done = p.start;
  for (size_t i = 0; i < ends.size(); ++i) {
    const double end = ends[i];
    if (p.chipEvery > 0) {
      for (double at = done; at < end;) {
        at = std::min(at + p.chipEvery, end);
        m.feed(centre, p.level(at), p.feed);
        if (at < p.depth) m.rapid(centre, p.level(at - p.chipBack));
      }
    } else {
      m.feed(centre, p.level(end), p.feed);
      if (i < reentries) {
        const double adv = reentries > 1 ? p.advFirst + (p.advLast - p.advFirst) * i / (reentries - 1) : p.advFirst;
        m.rapid(centre, p.level(p.removal));
        m.rapid(centre, p.level(end - adv));
      }
    }
    done = end;
  }
  return true;
}

}  // namespace ncc
