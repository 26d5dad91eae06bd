// main() of an executable from `ncc compile --emit=exe`: the part program linked in (its entry
// and description) run as `ncc run` runs it. Alone in its library (libncc_main.a), so programs
// that link compiled part programs into their own main never pull it in.
#include "runtime/ncrt.h"

int main(int argc, char **argv) { return ncrt_main(argc, argv, ncc_program_main, ncc_program_info); }
