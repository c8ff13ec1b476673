// The docs page of every diagnostic code, compiled into rung (generated from docs/diagnostics).
#pragma once

#include <span>
#include <string_view>

namespace rung::cli {

struct ExplainPage {
  std::string_view code;
  std::string_view markdown;
};

std::span<const ExplainPage> explain_pages();

}  // namespace rung::cli
