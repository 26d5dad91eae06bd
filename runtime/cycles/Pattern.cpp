#include "runtime/cycles/Pattern.h"
#include "runtime/Geometry.h"

#include <cmath>
#include <set>

namespace ncc {


std::vector<PlanePoint> linePattern(PlanePoint o, double degrees, double first, double spacing, int count) {
  double c, s;
  sinCosDegrees(degrees, s, c);
  std::vector<PlanePoint> out;
  for (int i = 0; i < count; ++i) {
    double d = first + i * spacing;
    out.push_back({o[0] + d * c, o[1] + d * s});
  }
  return out;
}

std::vector<PlanePoint> circlePattern(PlanePoint centre, double radius, double start, double step, int count) {
  std::vector<PlanePoint> out;
  for (int i = 0; i < count; ++i) {
    double c, s;
    sinCosDegrees(start + i * step, s, c);
    out.push_back({centre[0] + radius * c, centre[1] + radius * s});
  }
  return out;
}

std::vector<PlanePoint> gridPattern(PlanePoint o, double degrees, double d1, double d2, int n1, int n2, bool meander,
                                    bool frameOnly) {
  return shearedGridPattern(o, degrees, degrees, d1, d2, n1, n2, meander, frameOnly);
}

std::vector<PlanePoint> shearedGridPattern(PlanePoint o, double degrees1, double degrees2, double d1, double d2, int n1,
                                           int n2, bool meander, bool frameOnly) {
  double c1, s1, c2, s2;
  sinCosDegrees(degrees1, s1, c1);
  sinCosDegrees(degrees2, s2, c2);
  std::vector<PlanePoint> out;
  for (int j = 0; j < n2; ++j)
    for (int k = 0; k < n1; ++k) {
      int i = meander && (j % 2) ? n1 - 1 - k : k;
      if (frameOnly && j != 0 && j != n2 - 1 && i != 0 && i != n1 - 1) continue;
      double u = i * d1, v = j * d2;
      out.push_back({o[0] + u * c1 - v * s2, o[1] + u * s1 + v * c2});
    }
  return out;
}

bool hidePositions(std::vector<PlanePoint> &pts, const std::string &list, std::string &err) {
  std::set<long> hidden;
  size_t i = 0;
  while (i < list.size()) {
    while (i < list.size() && (list[i] == ' ' || list[i] == ',')) ++i;
    if (i == list.size()) break;
    char *end = nullptr;
    long a = std::strtol(list.c_str() + i, &end, 10), b = a;
    if (end == list.c_str() + i || a < 1) {
      err = "position list '" + list + "': expected numbers from 1, separated by commas";
      return false;
    }
    i = end - list.c_str();
    if (i < list.size() && list[i] == '-') {
      b = std::strtol(list.c_str() + i + 1, &end, 10);
      if (end == list.c_str() + i + 1 || b < a) {
        err = "position list '" + list + "': bad range";
        return false;
      }
      i = end - list.c_str();
    }
    for (long k = a; k <= b && k <= (long)pts.size(); ++k) hidden.insert(k);
  }
  std::vector<PlanePoint> kept;
  for (size_t k = 0; k < pts.size(); ++k)
    if (!hidden.count((long)k + 1)) kept.push_back(pts[k]);
  pts = std::move(kept);
  return true;
}

}  // namespace ncc
