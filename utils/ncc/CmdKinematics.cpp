// ncc kinematics: the machine's rotary kinematics (runtime/Kinematics.h) on one pose, to see
// which axis positions a tool tip and tool axis need, or where given axis positions put the tool.
//   ncc kinematics --machine FILE --tip X,Y,Z --axis I,J,K [--from X,Y,Z,A,B,C] [--tool-length L]
//   ncc kinematics --machine FILE --joints X,Y,Z,A,B,C [--tool-length L]
#include "runtime/Kinematics.h"
#include "utils/ncc/Driver.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <sstream>

namespace ncc::driver {

namespace {

constexpr const char *kAxisNames = "XYZABC";

// "1,2,3" into n..max numbers; false when malformed.
bool numbers(const std::string &s, size_t n, size_t max, std::vector<double> &out) {
  std::stringstream in(s);
  std::string item;
  out.clear();
  while (std::getline(in, item, ',')) {
    char *end = nullptr;
    double d = std::strtod(item.c_str(), &end);
    if (item.empty() || *end || !std::isfinite(d)) return false;
    out.push_back(d);
  }
  return out.size() >= n && out.size() <= max;
}

std::string num(double v) {
  std::string s = fmt::format("{:.4f}", v);
  return s == "-0.0000" ? "0.0000" : s;
}

// The machine's axes with their values: "X=1.0000 Y=… A=…".
std::string axesText(const Machine &m, const AxisVec &v) {
  std::string s;
  for (int i = 0; i < kAxes; ++i)
    if (m.axes[i].present) s += fmt::format("{}{}={}", s.empty() ? "" : " ", kAxisNames[i], num(v[i]));
  return s;
}

std::string vecText(const Vec3 &v) { return num(v[0]) + " " + num(v[1]) + " " + num(v[2]); }

}  // namespace

int cmdKinematics(int argc, char **argv) {
  Session s;
  std::string tip, axis, from, joints;
  double toolLength = 0;
  po::options_description desc("ncc kinematics options");
  desc.add_options()
      ("tip", po::value(&tip), "inverse: tool tip X,Y,Z in the workpiece frame, mm")
      ("axis", po::value(&axis), "inverse: tool axis I,J,K (tip to spindle) in the workpiece frame")
      ("from", po::value(&from), "inverse: the current axis positions X,Y,Z[,A,B,C] (default all 0)")
      ("joints", po::value(&joints), "forward: axis positions X,Y,Z[,A,B,C] (mm, degrees)")
      ("tool-length", po::value(&toolLength), "tool length from the gauge point to the tip, mm (default 0)");
  addCommonOptions(desc, s.opts);
  po::positional_options_description pos;
  po::variables_map vm;
  int rc = parseArgs(argc, argv, desc, pos, vm,
                     "ncc kinematics --machine FILE (--tip X,Y,Z --axis I,J,K [--from X,Y,Z,A,B,C] | --joints X,Y,Z,A,B,C)");
  if (rc >= 0) return rc;
  auto usage = [](const char *msg) {
    std::fprintf(stderr, "ncc: error: %s\n", msg);
    return kExitUsage;
  };
  bool inverse = !tip.empty() || !axis.empty();
  if (inverse == !joints.empty()) return usage("give --tip and --axis (inverse) or --joints (forward)");
  std::vector<double> t, a, q;
  AxisVec current{};
  if (inverse && (!numbers(tip, 3, 3, t) || !numbers(axis, 3, 3, a))) return usage("--tip and --axis want 3 numbers each");
  if (!numbers(inverse ? from.empty() ? "0,0,0" : from : joints, 3, kAxes, q))
    return usage("--from and --joints want 3 to 6 numbers X,Y,Z[,A,B,C]");
  std::copy(q.begin(), q.end(), current.begin());
  if (!s.setUp()) return kExitErrors;
  const Machine &m = s.machine;
  Kinematics kin(m);
  std::string out = fmt::format("kinematics {}", m.kinematics);
  for (auto &j : m.chain.joints)
    out += fmt::format(", {} ({} about ({}) through ({}))", kAxisNames[j.axis], j.onHead ? "head" : "table",
                       fmt::join(j.direction, ", "), fmt::join(j.center, ", "));
  out += "\n";
  if (!inverse) {
    ToolPose p = kin.forward(current, toolLength);
    out += fmt::format("tip {}\naxis {}\n", vecText(p.tip), vecText(p.axis));
    std::fputs(out.c_str(), stdout);
    return kExitOk;
  }
  InverseResult r = kin.inverse({{t[0], t[1], t[2]}, {a[0], a[1], a[2]}}, current, toolLength);
  for (size_t i = 0; i < r.solutions.size(); ++i) {
    auto &sol = r.solutions[i];
    out += fmt::format("{} {}{}\n", (int)i == r.chosen ? "*" : " ", axesText(m, sol.joints),
                       sol.problem.empty() ? "" : "  (" + sol.problem + ")");
  }
  if (r.singular) {
    int free = m.chain.joints[1 - m.chain.tiltJoint()].axis;
    out += fmt::format("singular: the tool axis lies along {}'s axis; {} keeps its position\n", kAxisNames[free],
                       kAxisNames[free]);
  }
  std::fputs(out.c_str(), stdout);
  std::fflush(stdout);  // before the error, so the solutions come first in a merged stream
  if (!r.ok()) {
    s.diags.error({}, r.error);
    return kExitErrors;
  }
  return kExitOk;
}

}  // namespace ncc::driver
