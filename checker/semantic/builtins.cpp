#include "checker/semantic/builtins.hpp"

#include <array>

#include "checker/symbols/names.hpp"

namespace rung::check {
namespace {

// CODESYS V3 / TwinCAT 3 operators and implicit objects (CODESYS online help "Operators";
// TwinCAT "Implicit variables"). Result types only where they never depend on the arguments.
constexpr std::array kBuiltins = {
    // CODESYS 2.3 TIME(): milliseconds since the controller started (OSCAT uses it).
    Builtin{"TIME", "TIME", false, true},
    // rung's LTIME-resolution clock: nanoseconds since the controller started (the LTIME timers and
    // RTC in library/ read it; docs/library.md).
    Builtin{"__LTIME", "LTIME", false, true},
    Builtin{"__NEW", nullptr, false, true},
    Builtin{"__DELETE", nullptr, false, true},
    Builtin{"__ISVALIDREF", "BOOL", false, true},
    Builtin{"__QUERYINTERFACE", "BOOL", false, true},
    Builtin{"__QUERYPOINTER", "BOOL", false, true},
    Builtin{"__VARINFO", nullptr, false, true},
    Builtin{"__POUNAME", "STRING", false, true},
    Builtin{"__POSITION", "STRING", false, true},
    Builtin{"__COMPARE_AND_SWAP", "BOOL", false, true},
    Builtin{"__XADD", "DINT", false, true},
    Builtin{"TEST_AND_SET", "BOOL", false, true},
    Builtin{"INI", "BOOL", false, true},
    Builtin{"UPPER_BOUND", "DINT", false, true},
    Builtin{"LOWER_BOUND", "DINT", false, true},
    Builtin{"XSIZEOF", nullptr, false, true},
    Builtin{"ADRINST", nullptr, false, true},
    Builtin{"INDEXOF", nullptr, false, true},
    Builtin{"REF", nullptr, false, true},
    Builtin{"__SYSTEM", nullptr, true, false},
    Builtin{"TwinCAT_SystemInfoVarList", nullptr, true, false},
    Builtin{"_TaskInfo", nullptr, true, false},
    Builtin{"_AppInfo", nullptr, true, false},
    Builtin{"NULL", nullptr, false, false},
    Builtin{"SFCInit", "BOOL", false, false},
    Builtin{"SFCReset", "BOOL", false, false},
    Builtin{"SFCPause", "BOOL", false, false},
    Builtin{"SFCError", "BOOL", false, false},
    Builtin{"SFCTrans", "BOOL", false, false},
    Builtin{"SFCCurrentStep", "STRING", false, false},
    Builtin{"SFCQuitError", "BOOL", false, false},
    Builtin{"SFCEnableLimit", "BOOL", false, false},
    Builtin{"SFCTip", "BOOL", false, false},
    Builtin{"SFCTipMode", "BOOL", false, false},
    Builtin{"SFCErrorStep", "STRING", false, false},
    Builtin{"SFCErrorPOU", "STRING", false, false},
    Builtin{"SFCErrorAnalyzation", "STRING", false, false},
};

}  // namespace

const Builtin* find_builtin(std::string_view name) {
  for (const auto& builtin : kBuiltins) {
    if (names_equal(builtin.name, name)) return &builtin;
  }
  return nullptr;
}

}  // namespace rung::check
