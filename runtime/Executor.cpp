// Scaffold: replaced by the executor implementation.
#include "runtime/Executor.h"
namespace ncc {
struct Executor::Impl { ModalState st; };
Executor::Executor(const Machine &, MotionSink &, Diagnostics &) : impl_(new Impl) {}
Executor::~Executor() { delete impl_; }
bool Executor::exec(const MachineCmd &) { return true; }
bool Executor::finish() { return true; }
const ModalState &Executor::state() const { return impl_->st; }
}
