#include "ir/SystemAccess.h"

namespace ncc {

bool readSystemValue(CmdSink &sink, ValuePool &pool, const SysRef &ref, double &out, std::string &err) {
  if (!sysVarIsFrame(ref.var)) return sink.readSystem(ref, out, err);
  FrameValue f;
  return sink.readFrame(ref, f, err) && pool.frames.intern(f, out, err);
}

bool writeSystemValue(CmdSink &sink, ValuePool &pool, const SysRef &ref, double v, SourceLoc loc, std::string &err) {
  if (sysVarIsFrame(ref.var)) {
    if (!isFrame(v)) {
      err = "system variable '$" + sysRefText(ref) + "' holds a frame, not a " + handleKind(v);
      return false;
    }
    FrameValue f = pool.frames.get(v);  // a copy: the sink may run code that grows the pool
    return sink.writeFrame(ref, f, loc, err);
  }
  if (isHandle(v)) {
    err = handleMessage(HandleUse::AsNumber, handleKind(v));
    return false;
  }
  return sink.writeSystem(ref, v, loc, err);
}

}  // namespace ncc
