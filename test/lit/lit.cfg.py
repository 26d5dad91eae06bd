import os
import shutil
import lit.formats

config.name = "ncc"
config.test_format = lit.formats.ShTest(execute_external=False)
config.suffixes = [".test", ".nc", ".ngc", ".ncir", ".mpf"]
config.excludes = ["Inputs", "lit.cfg.py", "lit.site.cfg.py.in"]
config.test_source_root = os.path.dirname(__file__)
config.test_exec_root = os.path.join(config.ncc_obj_root, "test", "lit")

llvm_bin = "/usr/lib/llvm-19/bin"
config.environment["PATH"] = os.pathsep.join(
    [config.ncc_tools_dir, llvm_bin, config.environment.get("PATH", os.environ.get("PATH", ""))])
config.substitutions.append(("%ncc", os.path.join(config.ncc_tools_dir, "ncc")))
config.substitutions.append(("%src", config.ncc_src_root))
config.substitutions.append(("%shared", os.path.normpath(os.path.join(config.ncc_src_root, "..", "shared"))))
if shutil.which("rs274"):
    config.available_features.add("rs274")
