// Resolving the keyword feeds of a cycle's arguments (CycleFeed.h).
#include "runtime/cycles/CycleFeed.h"
#include "runtime/cycles/Entry.h"
#include "ir/WordList.h"

#include <fmt/format.h>

#include <cstring>
#include <string_view>

namespace ncc::cyclefeed {

namespace {
// The Heidenhain feed parameters (mm/min, or a keyword where the manual's text allows one):
// Q206 plunging, Q207 milling, Q208 retraction, Q253 pre-positioning, Q254 countersinking /
// back boring, Q385 finishing, Q512 approach.
constexpr const char *kFeedParams[] = {"Q206", "Q207", "Q208", "Q253", "Q254", "Q385", "Q512"};

// Where FMAX is honoured: the entry hands the parameter to straight moves as it is (no
// arithmetic on it, no arcs), so a step at kRapid becomes a traverse. Checked against each
// entry's code: 201-203, 205 and 241 retract at Q208 (Hole.h exitFeed / fullRetractFeed,
// HeiDeepHole.cpp); 204, 205, 241, 262-267, 232 and 233 pre-position at Q253; the studs 256 and
// 257 plunge beside the material at Q206 (Stud.cpp).
struct RapidOk {
  const char *entry;
  const char *params;
};
constexpr RapidOk kRapidOk[] = {
    {"hei.201", "Q208"},      {"hei.202", "Q208"}, {"hei.203", "Q208"}, {"hei.204", "Q253"},
    {"hei.205", "Q208 Q253"}, {"hei.241", "Q208 Q253"}, {"hei.262", "Q253"}, {"hei.263", "Q253"},
    {"hei.264", "Q253"},      {"hei.265", "Q253"}, {"hei.267", "Q253"}, {"hei.232", "Q253"},
    {"hei.233", "Q253"},      {"hei.256", "Q206"}, {"hei.257", "Q206"},
};


bool rapidHonoured(const CycleDef &def, std::string_view q) {
  for (const RapidOk &r : kRapidOk)
    if (std::strcmp(r.entry, def.name) == 0) return inWordList(r.params, q);
  return false;
}
}  // namespace

bool resolve(const CycleDef &def, CycleArgs &args, const Spindle &s, std::string &err) {
  if (std::string_view(def.name).substr(0, 4) != "hei.") return true;
  for (const char *q : kFeedParams) {
    auto it = args.num.find(q);
    if (it == args.num.end()) continue;
    double &v = it->second;
    if (v == kRapid) {
      if (!rapidHonoured(def, q)) return entry::unsupported(err, fmt::format("{}=FMAX is not simulated for this cycle", q));
      continue;
    }
    const bool perRev = v <= kPerRev && v > kPerRev - kBand, perTooth = v <= kPerTooth && v > kPerTooth - kBand;
    if (!perRev && !perTooth) continue;
    const char *kw = perRev ? "FU" : "FZ";
    if (!(s.speed > 0))
      return entry::fail(err, fmt::format("{}={}: a feed per {} needs a spindle speed (S in TOOL CALL)", q, kw,
                                          perRev ? "revolution" : "tooth"));
    if (perTooth && s.teeth <= 0)
      return entry::fail(err, fmt::format("{}=FZ: a feed per tooth needs the tool's number of teeth (`teeth` of its "
                                          "[[tools]] entry, the TNC's CUT)", q));
    v = perRev ? (kPerRev - v) * s.speed : (kPerTooth - v) * s.teeth * s.speed;
  }
  return true;
}

}  // namespace ncc::cyclefeed
