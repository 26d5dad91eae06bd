// The file commands WRITE, DELETE, READ and FILEDATE/FILETIME/FILESIZE/FILESTAT/FILEINFO
// (L6287-L6787): each stores the manual's error code into its first argument (a variable, by
// reference) and works through the file builtins of both engines (ir/FileCommands.h), which
// confine the files to the `--sandbox` folder. ISFILE is a function (Codes.cpp).
#include "frontend/sinumerik/Parser.h"
#include "ir/Strings.h"

#include <fmt/format.h>

namespace ncc::sin {

namespace {
// FILExxx: what FILE_INFO returns and the shortest result string it needs (L6740-L6766).
struct InfoCommand {
  const char *name;
  const char *what;  // FILE_INFO's selector; null: FILESIZE (FILE_SIZE, a number)
  unsigned length;
};
const InfoCommand kInfo[] = {
    {"FILEDATE", "DATE", 8}, {"FILETIME", "TIME", 8}, {"FILESIZE", nullptr, 0},
    {"FILESTAT", "STAT", 5}, {"FILEINFO", "INFO", 32},
};
// More lines than this in one READ would unroll into too large a program.
constexpr double kMaxReadLines = 1000;

ir::ExprPtr fileCall(const char *fn, const std::string &cmd, SourceLoc l, std::vector<ir::ExprPtr> args) {
  args.insert(args.begin(), ir::Expr::string(cmd, l));
  return ir::Expr::call(fn, std::move(args), l);
}

ir::Op ifZero(const ir::Expr &err, SourceLoc l) {
  ir::Op iff(ir::OpKind::If, l);
  iff.set("cond", ir::Expr::binary(ir::OpCode::Eq, err.clone(), ir::Expr::number(0, ir::Type::Int, l), l));
  iff.regions.emplace_back();
  return iff;
}
}  // namespace

bool BlockParser::fileCommand(const std::string &kw) {
  const InfoCommand *info = nullptr;
  for (auto &c : kInfo)
    if (kw == c.name) info = &c;
  if (!info && kw != "WRITE" && kw != "DELETE" && kw != "READ") return false;
  if (f_.vars.count(kw)) return false;
  const Token &at = tok();
  SourceLoc l = loc(at);
  ++i_;
  if (!expect("(")) return true;
  // The arguments: the error variable, then expressions (READ's and FILExxx's result: a variable).
  std::vector<ir::ExprPtr> args;
  std::vector<const Token *> starts;
  do {
    starts.push_back(&tok());
    ir::ExprPtr e = expr(0);
    if (!e) return true;
    args.push_back(std::move(e));
  } while (tok().is(",") && (++i_, true));
  if (!expect(")")) return true;
  size_t want = kw == "READ" ? 5 : kw == "DELETE" ? 2 : 3;
  if (args.size() != want) return fail(at, fmt::format("{} takes {} arguments, found {}", kw, want, args.size())), true;
  auto isVar = [&](size_t i, const char *what) {
    if (args[i]->kind == ir::ExprKind::Var) return true;
    fail(*starts[i], fmt::format("{}'s {} must be a variable", kw, what));
    return false;
  };
  if (!isVar(0, "error argument")) return true;
  if (!stringy(*args[1])) return fail(*starts[1], fmt::format("{}'s file name must be a string", kw)), true;
  if (kw == "WRITE" && !stringy(*args[2])) return fail(*starts[2], "WRITE's text must be a string"), true;
  ir::ExprPtr err = std::move(args[0]);
  ir::ExprPtr file = std::move(args[1]);
  std::vector<ir::ExprPtr> a;
  a.push_back(file->clone());
  if (kw == "WRITE" || kw == "DELETE") {
    if (kw == "WRITE") a.push_back(std::move(args[2]));
    pre_.push_back(assignOp(std::move(err), fileCall(kw == "WRITE" ? "FILE_WRITE" : "FILE_DELETE", kw, l, std::move(a)), l));
    return true;
  }
  if (info) {  // err = FILE_STATUS; if err == 0 { result = FILE_INFO } (22 when the result is too short)
    if (!isVar(2, "result")) return true;
    ir::ExprPtr result = std::move(args[2]);
    auto d = f_.vars.find(result->str);
    bool isString = d != f_.vars.end() && d->second.type == ir::Type::String;
    if (info->what ? !isString : isString)
      return fail(*starts[2], fmt::format("{}'s result must be a {}", kw, info->what ? "STRING" : "number")), true;
    pre_.push_back(assignOp(err->clone(), fileCall("FILE_STATUS", kw, l, std::move(a)), l));
    ir::Op iff = ifZero(*err, l);
    unsigned len = info->what ? (d->second.len ? d->second.len : kDefaultStringLength) : 0;
    if (info->what && !d->second.isChar && len < info->length) {
      iff.regions[0].push_back(assignOp(std::move(err), ir::Expr::number(22, ir::Type::Int, l), l));
    } else {
      std::vector<ir::ExprPtr> b;
      b.push_back(std::move(file));
      if (info->what) b.push_back(ir::Expr::string(info->what, l));
      iff.regions[0].push_back(assignOp(std::move(result), fileCall(info->what ? "FILE_INFO" : "FILE_SIZE", kw, l, std::move(b)), l));
    }
    pre_.push_back(std::move(iff));
    return true;
  }
  // READ(err, file, start, count, result): a STRING array; the lines unrolled, so the count is
  // a constant.
  if (!isVar(4, "result")) return true;
  const ir::Expr &result = *args[4];
  auto d = f_.vars.find(result.str);
  if (d == f_.vars.end() || d->second.type != ir::Type::String || d->second.dims.empty() || !result.args.empty())
    return fail(*starts[4], "READ's result must be a STRING array, named without an index"), true;
  if (args[3]->kind != ir::ExprKind::Number || args[3]->num < 1 || args[3]->num > kMaxReadLines)
    return fail(*starts[3], fmt::format("READ's line count must be a constant from 1 to {}", kMaxReadLines),
                "unsupported-code"),
           true;
  const VarDecl &decl = d->second;
  size_t elements = elementCount(decl);
  size_t count = (size_t)args[3]->num;
  a.push_back(args[2]->clone());
  a.push_back(args[3]->clone());
  a.push_back(ir::Expr::number((double)elements, ir::Type::Int, l));
  pre_.push_back(assignOp(err->clone(), fileCall("FILE_READ_STATUS", kw, l, std::move(a)), l));
  ir::Op iff = ifZero(*err, l);
  double len = decl.len ? decl.len : kDefaultStringLength;
  for (size_t k = 0; k < count && k < elements; ++k) {
    auto target = ir::Expr::var(decl.global ? ir::VarSpace::Global : ir::VarSpace::Local, result.str, nullptr, l);
    size_t rest = k;  // row-major: the last index fastest
    std::vector<ir::ExprPtr> idx(decl.dims.size());
    for (size_t j = decl.dims.size(); j-- > 0;) {
      idx[j] = ir::Expr::number((double)(rest % decl.dims[j]), ir::Type::Int, l);
      rest /= decl.dims[j];
    }
    target->args = std::move(idx);
    std::vector<ir::ExprPtr> b;
    b.push_back(file->clone());
    b.push_back(args[2]->clone());
    b.push_back(args[3]->clone());
    b.push_back(ir::Expr::number((double)k, ir::Type::Int, l));
    b.push_back(ir::Expr::number(len, ir::Type::Int, l));
    iff.regions[0].push_back(assignOp(std::move(target), fileCall("FILE_LINE", kw, l, std::move(b)), l));
  }
  pre_.push_back(std::move(iff));
  return true;
}

}  // namespace ncc::sin
