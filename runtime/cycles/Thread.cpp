#include "runtime/cycles/Thread.h"

#include <cmath>

namespace ncc {

void threadPass(const ThreadPass &p, std::vector<ThreadStep> &out) {
  using K = ThreadStepKind;
  auto step = [&](K k, double x, double z, double lead) { out.push_back({k, x, z, lead, p.alongPath}); };
  step(K::Rapid, p.retractX, p.startZ, 0);  // back
  double z0 = p.startZ;
  if (p.entry) {
    step(K::Start, p.entryX, p.startZ, p.entryLead);  // in
    z0 = p.startZ + p.entryDz;
    step(K::Chain, p.startX, z0, p.entryLead);  // angled in
  } else {
    step(K::Rapid, p.startX, p.startZ, 0);  // in
  }
  const K cut = p.entry ? K::Chain : K::Start;
  if (p.exit) {
    step(cut, p.endX, p.endZ - p.exitDz, p.lead);  // over
    step(K::Chain, p.exitX, p.endZ, p.exitLead);   // angled out
  } else {
    step(cut, p.endX, p.endZ, p.lead);  // over
  }
  step(K::Rapid, p.retractX, p.endZ, 0);  // out
}

std::vector<double> lcncThreadDepths(double offset, double first, double full, double degression, int springPasses) {
  std::vector<double> d;
  const double end = full + offset;
  double depth = offset + first;
  for (int pass = 1; depth < end;) {
    d.push_back(depth);
    depth = offset + first * std::pow(++pass, 1.0 / degression);
  }
  for (int i = 0; i < springPasses + 1; ++i) d.push_back(end);
  return d;
}

std::vector<double> fanucThreadDepths(double height, double first, double minCut, double allowance, int finishPasses) {
  std::vector<double> d;
  const double rough = height - allowance;
  double depth = first;
  for (int n = 1; depth < rough;) {
    d.push_back(depth);
    double next = first * std::sqrt(++n);
    depth = next - depth < minCut ? depth + minCut : next;
  }
  if (allowance > 0) d.push_back(rough);
  for (int i = 0; i < finishPasses; ++i) d.push_back(height);
  return d;
}

}  // namespace ncc
