# find_package(ncc): link compiled part programs (ncc compile --emit=obj) into a program.
#   ncc::runtime  the runtime (ncrt_* C ABI, executor, outputs, ncrt_main); headers <runtime/ncrt.h>
#   ncc::main     main() running the one linked program as `ncc run` does (what --emit=exe links)
include(CMakeFindDependencyMacro)
find_dependency(fmt)
find_dependency(tomlplusplus)
find_dependency(Boost COMPONENTS program_options)
include(${CMAKE_CURRENT_LIST_DIR}/nccTargets.cmake)
