// Scaffold: replaced by the machine-description parser.
#include "runtime/Machine.h"
namespace ncc {
const Machine &Machine::builtinDefault() { static Machine m; return m; }
}
