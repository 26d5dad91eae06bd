# lit configuration for ncc. ctest runs each area folder with --param ncc_obj_root=<build dir>.
import os
import shutil
import lit.formats

config.name = "ncc"
config.test_format = lit.formats.ShTest(execute_external=False)
config.suffixes = [".test", ".nc", ".ngc", ".ncir", ".mpf"]
config.excludes = ["Inputs", "lit.cfg.py"]
config.test_source_root = os.path.dirname(__file__)

obj_root = lit_config.params.get("ncc_obj_root") or os.environ.get("NCC_OBJ_ROOT") or \
    os.path.join(os.path.dirname(__file__), "..", "..", "build")
obj_root = os.path.abspath(obj_root)
# ctest runs the areas in parallel: each gets its own exec root, because lit rewrites the
# suite's .lit_test_times.txt at exit without locking, and a file torn by two writers stops
# every later lit run while reading it.
config.test_exec_root = os.path.join(obj_root, "test", "lit", lit_config.params.get("ncc_lit_run", ""))
tools = os.path.join(obj_root, "utils")
src_root = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

llvm_bin = "/usr/lib/llvm-19/bin"
config.environment["PATH"] = os.pathsep.join([tools, llvm_bin, os.environ.get("PATH", "")])
# Every diagnostic's rule id must be in the registry (ir/LintRules.cpp): ncc aborts otherwise.
config.environment["NCC_CHECK_RULES"] = "1"
config.substitutions.append(("%ncc", os.path.join(tools, "ncc")))
config.substitutions.append(("%srcroot", src_root))
config.substitutions.append(("%objroot", obj_root))
config.substitutions.append(("%shared", os.path.normpath(os.path.join(src_root, "..", "shared"))))
if os.path.isdir(os.path.join(src_root, "..", "shared", "spec")):
    config.available_features.add("shared")
if shutil.which("rs274"):
    config.available_features.add("rs274")
