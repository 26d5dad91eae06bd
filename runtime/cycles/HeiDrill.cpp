#include "runtime/cycles/HeiDrill.h"
#include "runtime/cycles/Hole.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ncc {

bool infeedEnds(double start, double depth, double infeed, double decrement, double minInfeed, std::vector<double> &ends,
                std::string &err) {
  for (double at = start, step = infeed; at < depth;) {
    at = step > 0 ? std::min(at + step, depth) : depth;
    ends.push_back(at);
    if (decrement > 0 && std::max(step - decrement, minInfeed) > 0) step = std::max(step - decrement, minInfeed);
    if (ends.size() > kMaxPecks) return err = "the infeed (Q202, Q205 or Q257) is too small: more than a million infeeds", false;
  }
  return true;
}

bool peckDrill(Mill &m, const PeckPlan &p, std::string &err) {
  const char *tooSmall = "the infeed (Q202, Q205 or Q257) is too small: more than a million infeeds";
  if (p.chipEvery > 0 && (p.depth - p.start) / p.chipEvery > kMaxPecks) return err = tooSmall, false;
  // The infeeds' ends first: the advance distances spread over the re-entries between them.
  std::vector<double> ends;
  if (!infeedEnds(p.start, p.depth, p.infeed, p.decrement, p.minInfeed, ends, err)) return false;
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
