// Sinumerik file commands (WRITE, READ, DELETE, ISFILE, FILEDATE …) as typed builtins of both
// engines (ir/Builtins.h). Files live only inside the sandbox folder the driver sets
// (`--sandbox DIR`): without one each command is a run-time error naming it, and a name that
// would leave the folder is an error too. Names map onto the folder as docs/SINUMERIK.md "Files"
// says (`PROT` → PROT.MPF, `/_N_WKS_DIR/_N_P_WPD/_N_PROT_MPF` → WKS.DIR/P.WPD/PROT.MPF).
#pragma once
#include <string>
#include <string_view>

namespace ncc {

class ValuePool;

// One component of a Sinumerik path as a file or folder name: `_N_NAME_EXT` -> NAME.EXT (`_N_WKS_DIR`
// is WKS.DIR); `last`: a file name without a type is an MPF (L6393: "PROT" is _N_PROT_MPF).
std::string sinumerikPathComponent(std::string_view c, bool last);

// The sandbox folder for the run (the process): empty = none.
void setFileSandbox(std::string dir);
const std::string &fileSandbox();
// ncc lint's run: WRITE and DELETE touch nothing (and report 0); without a sandbox the other
// commands find no folder (code 2, ISFILE false) instead of stopping the run.
void setFileLintMode(bool on);

// The builtins (first argument: the Sinumerik command, for error texts):
//   FILE_WRITE(cmd, file, text)      -> error code; appends text and a line feed
//   FILE_DELETE(cmd, file)           -> error code
//   FILE_EXISTS(cmd, file)           -> 1 / 0 (ISFILE)
//   FILE_STATUS(cmd, file)           -> error code of a file to read (0, 2, 3, 4)
//   FILE_INFO(cmd, file, what)       -> DATE "dd.mm.yy", TIME "hh:mm.ss", STAT "77777",
//                                       INFO "77777 nnnnnnnn dd.mm.yy hh:mm:ss" ("" when unreadable)
//   FILE_SIZE(cmd, file)             -> bytes (0 when unreadable)
//   FILE_READ_STATUS(cmd, file, start, count, elements) -> READ's error code
//   FILE_LINE(cmd, file, start, count, k, length)       -> line k of READ's range, cut to length
#define NCC_FILE_BUILTIN(NAME) bool NAME(ValuePool &pool, const double *args, unsigned n, double &out, std::string &error)
NCC_FILE_BUILTIN(fileWrite);
NCC_FILE_BUILTIN(fileDelete);
NCC_FILE_BUILTIN(fileExists);
NCC_FILE_BUILTIN(fileStatus);
NCC_FILE_BUILTIN(fileInfo);
NCC_FILE_BUILTIN(fileSize);
NCC_FILE_BUILTIN(fileReadStatus);
NCC_FILE_BUILTIN(fileLine);
#undef NCC_FILE_BUILTIN

}  // namespace ncc
