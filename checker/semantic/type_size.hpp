// How many bytes a value of a type occupies on a CODESYS V3 / TwinCAT 3 64-bit target: for
// SIZEOF, whose result type grows with the size (USINT below 256 bytes, UINT below 65536, UDINT
// below 2**32, else ULINT), and later for the runner's memory layout.
#pragma once

#include <cstdint>
#include <optional>

#include "checker/project_model.hpp"

namespace rung::check {

struct TypeLayout {
  uint64_t size = 0;       // bytes
  uint64_t alignment = 1;  // bytes; structures are padded to it (pack_mode 8, the default)
};

// nullopt when the size is not fixed or not known (unknown types, FB instances, ARRAY[*]).
std::optional<TypeLayout> type_layout(const ProjectModel& model, const Type* type);

// The unsigned type SIZEOF returns for `bytes`.
const Type* sizeof_result_type(TypeArena& types, uint64_t bytes);

}  // namespace rung::check
