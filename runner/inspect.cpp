#include "runner/inspect.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>

#include <fmt/format.h>

#include "checker/constant/const_value.hpp"
#include "checker/symbols/names.hpp"
#include "runner/compile/lowering.hpp"
#include "runner/stdlib/datetime.hpp"
#include "runner/stdlib/text.hpp"

namespace rung::run {
namespace {

constexpr int kMaxDepth = 32;
constexpr size_t kMaxArrayElements = 100'000;  // larger arrays are cut in reports

Layouts& layouts_of(const CompiledProject& project) { return *project.layouts; }

bool read_bytes(const Machine& machine, uint64_t address, void* out, size_t size) {
  if (!machine.valid(address, size)) return false;
  std::memcpy(out, machine.memory() + address, size);
  return true;
}

// The raw slot of a scalar at `address`, sign- or zero-extended.
std::optional<Slot> read_scalar(const Machine& machine, Scalar scalar, uint64_t address) {
  Slot slot{};
  switch (scalar) {
    case Scalar::U8: { uint8_t v; if (!read_bytes(machine, address, &v, 1)) return std::nullopt; slot.u = v; break; }
    case Scalar::S8: {
      uint8_t v;
      if (!read_bytes(machine, address, &v, 1)) return std::nullopt;
      slot.i = v >= 128 ? static_cast<int64_t>(v) - 256 : static_cast<int64_t>(v);  // sign-extend
      break;
    }
    case Scalar::U16: { uint16_t v; if (!read_bytes(machine, address, &v, 2)) return std::nullopt; slot.u = v; break; }
    case Scalar::S16: { int16_t v; if (!read_bytes(machine, address, &v, 2)) return std::nullopt; slot.i = v; break; }
    case Scalar::U32: { uint32_t v; if (!read_bytes(machine, address, &v, 4)) return std::nullopt; slot.u = v; break; }
    case Scalar::S32: { int32_t v; if (!read_bytes(machine, address, &v, 4)) return std::nullopt; slot.i = v; break; }
    case Scalar::I64:
    case Scalar::U64: { if (!read_bytes(machine, address, &slot.u, 8)) return std::nullopt; break; }
    case Scalar::F32: { if (!read_bytes(machine, address, &slot.f32, 4)) return std::nullopt; break; }
    case Scalar::F64: { if (!read_bytes(machine, address, &slot.f64, 8)) return std::nullopt; break; }
    case Scalar::None: return std::nullopt;
  }
  return slot;
}

// The shortest text that reads back as the same float (REAL) or double (LREAL).
std::string shortest_real(double value, bool single) {
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "Infinity" : "-Infinity";
  return single ? fmt::format("{}", static_cast<float>(value)) : fmt::format("{}", value);
}

std::string enum_name(const Layouts& layouts, const check::Type* type, int64_t number) {
  if (!type->declaration) return {};
  for (const check::Symbol* member : type->declaration->ordered) {
    if (member->kind != check::SymbolKind::EnumValue) continue;
    if (auto value = layouts.model().enum_value(member); value && *value == number) return std::string(member->name);
  }
  return {};
}

std::string read_text(const Machine& machine, const check::Type* type, uint64_t address) {
  const bool wide = type->kind == check::TypeKind::WString;
  const uint64_t capacity = type->length;
  if (!wide) {
    std::string bytes;
    for (uint64_t i = 0; i < capacity && machine.valid(address + i, 1); ++i) {
      const auto c = static_cast<char>(machine.memory()[address + i]);
      if (c == 0) break;
      bytes += c;
    }
    return single_byte_to_utf8(bytes);
  }
  std::vector<uint16_t> units;
  for (uint64_t i = 0; i < capacity && machine.valid(address + 2 * i, 2); ++i) {
    uint16_t unit = 0;
    std::memcpy(&unit, machine.memory() + address + 2 * i, 2);
    if (unit == 0) break;
    units.push_back(unit);
  }
  return utf16_to_utf8(units.data(), units.size());
}

const check::Type* strip(const check::Type* type) {
  type = Layouts::storage_type(type);
  return type;
}

// Visible members of a struct or an FB/program instance, in declaration order (bases first).
std::vector<const check::Symbol*> members_of(Layouts& layouts, const check::Type* type) {
  std::vector<const check::Symbol*> members;
  if (!type->declaration) return members;
  if (type->kind == check::TypeKind::Pou) {
    // Variables a block hides ({attribute 'hide'}: a standard block's internal state) stay hidden.
    for (const check::Symbol* variable : layouts.pou(type->declaration).instance_variables) {
      if (!variable->has(check::kHide)) members.push_back(variable);
    }
    return members;
  }
  layouts.of(type);
  std::vector<const check::Symbol*> chain;
  for (const check::Symbol* s = type->declaration; s; s = s->base == s ? nullptr : s->base) chain.insert(chain.begin(), s);
  for (const check::Symbol* s : chain) {
    for (const check::Symbol* member : s->ordered) {
      if (member->kind == check::SymbolKind::Variable) members.push_back(member);
    }
  }
  return members;
}

nlohmann::ordered_json json_at(const CompiledProject& project, const Machine& machine, const check::Type* declared,
                       uint64_t address, int depth) {
  Layouts& layouts = layouts_of(project);
  const check::Type* type = strip(declared);
  if (!type || depth > kMaxDepth) return nullptr;
  using check::TypeKind;
  switch (type->kind) {
    case TypeKind::String:
    case TypeKind::WString: return read_text(machine, type, address);
    case TypeKind::Struct:
    case TypeKind::Union:
    case TypeKind::Pou: {
      if (type->kind == TypeKind::Pou && type->declaration && type->declaration->kind == check::SymbolKind::Interface) {
        break;
      }
      nlohmann::ordered_json object = nlohmann::ordered_json::object();
      for (const check::Symbol* member : members_of(layouts, type)) {
        ValueRef ref{member->type, address + layouts.offset(member)};
        if (Layouts::held_by_reference(member)) {
          uint64_t pointer = 0;
          read_bytes(machine, ref.address, &pointer, 8);
          // A VAR_IN_OUT or REFERENCE shows the value it refers to; null while it refers to nothing.
          if (!machine.valid(pointer, 1)) {
            object[std::string(member->name)] = nullptr;
            continue;
          }
          ref.address = pointer;
          if (member->type && member->type->kind == TypeKind::Reference) ref.type = member->type->element;
        }
        object[std::string(member->name)] = json_at(project, machine, ref.type, ref.address, depth + 1);
      }
      return object;
    }
    case TypeKind::Array: {
      const uint64_t element = layouts.of(type->element).size;
      // Nested JSON arrays for each dimension.
      std::function<nlohmann::ordered_json(size_t, uint64_t)> dimension = [&](size_t d, uint64_t at) -> nlohmann::ordered_json {
        nlohmann::ordered_json array = nlohmann::ordered_json::array();
        if (d >= type->dimensions.size()) return json_at(project, machine, type->element, at, depth + 1);
        const auto& dim = type->dimensions[d];
        uint64_t stride = element;
        for (size_t later = d + 1; later < type->dimensions.size(); ++later) {
          stride *= static_cast<uint64_t>(type->dimensions[later].upper - type->dimensions[later].lower + 1);
        }
        const auto count = static_cast<uint64_t>(std::max<int64_t>(0, dim.upper - dim.lower + 1));
        for (uint64_t i = 0; i < count && i < kMaxArrayElements; ++i) array.push_back(dimension(d + 1, at + i * stride));
        return array;
      };
      return dimension(0, address);
    }
    default: break;
  }
  const Scalar scalar = Layouts::scalar_of(type);
  auto slot = read_scalar(machine, scalar, address);
  if (!slot) return nullptr;
  switch (type->kind) {
    case TypeKind::Bool: return slot->u != 0;
    case TypeKind::Real: return scalar == Scalar::F32 ? nlohmann::ordered_json(std::stod(shortest_real(slot->f32, true)))
                                                     : nlohmann::ordered_json(slot->f64);
    case TypeKind::Duration:
      return duration_text(slot->i, time_unit_of(type), type->long_variant);
    case TypeKind::Date: return date_text(slot->i, time_unit_of(type), type->long_variant);
    case TypeKind::TimeOfDay: return time_of_day_text(slot->i, time_unit_of(type), type->long_variant);
    case TypeKind::DateTime: return date_and_time_text(slot->i, time_unit_of(type), type->long_variant);
    case TypeKind::Enum: {
      std::string name = enum_name(layouts, type, slot->i);
      if (!name.empty()) return name;
      return slot->i;
    }
    case TypeKind::Char: return single_byte_to_utf8(std::string(1, static_cast<char>(slot->u)));
    default: break;
  }
  if (scalar == Scalar::U8 || scalar == Scalar::U16 || scalar == Scalar::U32 || scalar == Scalar::U64) return slot->u;
  return slot->i;
}

std::string quote(std::string_view text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'') {
      out += "$'";
    } else if (c == '$') {
      out += "$$";
    } else if (c == '\n') {
      out += "$N";
    } else {
      out += c;
    }
  }
  return out + "'";
}

std::string text_from_json(const nlohmann::ordered_json& value, const check::Type* declared, Layouts& layouts) {
  const check::Type* type = strip(declared);
  if (value.is_null()) return "?";
  if (value.is_boolean()) return value.get<bool>() ? "TRUE" : "FALSE";
  if (value.is_string()) {
    if (type && (type->kind == check::TypeKind::String || type->kind == check::TypeKind::Char)) return quote(value.get<std::string>());
    if (type && (type->kind == check::TypeKind::WString || type->kind == check::TypeKind::WChar)) {
      return "\"" + value.get<std::string>() + "\"";
    }
    return value.get<std::string>();
  }
  if (value.is_number_float()) return shortest_real(value.get<double>(), type && type->bits == 32);
  if (value.is_number()) return value.dump();
  if (value.is_array()) {
    std::string out = "[";
    const check::Type* element = type && type->kind == check::TypeKind::Array ? type->element : nullptr;
    for (size_t i = 0; i < value.size(); ++i) {
      if (i > 0) out += ", ";
      // Nested arrays of one multi-dimensional type keep the element type.
      out += text_from_json(value[i], value[i].is_array() ? declared : element, layouts);
    }
    return out + "]";
  }
  if (value.is_object()) {
    std::string out = "(";
    bool first = true;
    std::vector<const check::Symbol*> members = type ? members_of(layouts, type) : std::vector<const check::Symbol*>{};
    for (const check::Symbol* member : members) {
      auto found = value.find(std::string(member->name));
      if (found == value.end()) continue;
      if (!first) out += ", ";
      first = false;
      out += std::string(member->name) + " := " + text_from_json(*found, member->type, layouts);
    }
    return out + ")";
  }
  return value.dump();
}

}  // namespace

ValueRef variable_ref(const Machine& machine, const VariableView& variable) {
  ValueRef ref{variable.type, variable.address, variable.bit};
  if (variable.by_reference) {
    uint64_t pointer = 0;
    read_bytes(machine, variable.address, &pointer, 8);
    ref.address = pointer;
    if (variable.type && variable.type->kind == check::TypeKind::Reference) ref.type = variable.type->element;
  }
  return ref;
}

nlohmann::ordered_json value_json(const CompiledProject& project, const Machine& machine, const ValueRef& ref) {
  if (ref.bit >= 0) {
    uint8_t byte = 0;
    if (!read_bytes(machine, ref.address, &byte, 1)) return nullptr;
    return ((byte >> ref.bit) & 1) != 0;
  }
  return json_at(project, machine, ref.type, ref.address, 0);
}

std::string value_text(const CompiledProject& project, const Machine& machine, const ValueRef& ref) {
  return text_from_json(value_json(project, machine, ref), ref.type, layouts_of(project));
}

// step.X and step.T of an SFC body: the state its chart keeps in the instance (SfcLayout).
std::optional<ValueRef> sfc_flag(Layouts& layouts, const check::Symbol* pou, uint64_t instance,
                                 const std::vector<std::string>& parts, size_t at) {
  if (!pou || at + 1 >= parts.size() || !check::is_pou_kind(pou->kind)) return std::nullopt;
  const PouLayout& layout = layouts.pou(pou);
  const int step = layout.sfc ? layout.sfc->step_index(parts[at]) : -1;
  if (step < 0) return std::nullopt;
  const uint64_t address = instance + layout.sfc->step_offset(static_cast<size_t>(step));
  if (check::names_equal(parts[at + 1], "X")) return ValueRef{layouts.model().types().elementary("BOOL"), address};
  if (check::names_equal(parts[at + 1], "T")) return ValueRef{layouts.model().types().elementary("TIME"), address + 4};
  return std::nullopt;
}

std::optional<ValueRef> resolve_path(const CompiledProject& project, const Machine& machine, std::string_view path,
                                     std::string* error) {
  Layouts& layouts = layouts_of(project);
  // Split into names and [index] groups.
  std::vector<std::string> parts;
  std::string current;
  for (size_t i = 0; i < path.size(); ++i) {
    const char c = path[i];
    if (c == '.') {
      if (!current.empty()) parts.push_back(current);
      current.clear();
    } else if (c == '[') {
      if (!current.empty()) parts.push_back(current);
      const size_t close = path.find(']', i);
      if (close == std::string_view::npos) {
        if (error) *error = fmt::format("'{}': '[' without ']'", path);
        return std::nullopt;
      }
      parts.push_back(std::string(path.substr(i, close - i + 1)));
      current.clear();
      i = close;
    } else if (c != ' ') {
      current += c;
    }
  }
  if (!current.empty()) parts.push_back(current);
  if (parts.empty()) {
    if (error) *error = "empty variable name";
    return std::nullopt;
  }
  std::optional<ValueRef> ref;
  size_t next = 0;
  auto find_in = [&](const std::vector<VariableView>& variables, std::string_view name) -> std::optional<ValueRef> {
    for (const VariableView& variable : variables) {
      if (check::names_equal(variable.name, name)) return variable_ref(machine, variable);
    }
    return std::nullopt;
  };
  for (const ProgramInstance& program : project.programs) {
    if (check::names_equal(program.name, parts[0]) && parts.size() > 1) {
      ref = find_in(program.variables, parts[1]);
      next = 2;
      if (!ref && (ref = sfc_flag(layouts, program.program, program.address, parts, 1))) next = 3;
      break;
    }
  }
  if (!ref) {
    for (const GlobalList& list : project.globals) {
      if (check::names_equal(list.name, parts[0]) && parts.size() > 1) {
        ref = find_in(list.variables, parts[1]);
        next = 2;
        break;
      }
    }
  }
  if (!ref) {
    for (const ProgramInstance& program : project.programs) {
      if ((ref = find_in(program.variables, parts[0]))) break;
    }
    if (!ref) {
      for (const GlobalList& list : project.globals) {
        if ((ref = find_in(list.variables, parts[0]))) break;
      }
    }
    next = 1;
  }
  if (!ref) {
    if (error) *error = fmt::format("there is no variable '{}'", path);
    return std::nullopt;
  }
  for (; next < parts.size(); ++next) {
    const std::string& part = parts[next];
    const check::Type* type = strip(ref->type);
    if (!type) break;
    if (part.front() == '[') {
      if (type->kind != check::TypeKind::Array) {
        if (error) *error = fmt::format("'{}' is not an array", path);
        return std::nullopt;
      }
      std::vector<int64_t> indexes;
      std::string inner = part.substr(1, part.size() - 2);
      size_t start = 0;
      while (start <= inner.size()) {
        size_t comma = inner.find(',', start);
        if (comma == std::string::npos) comma = inner.size();
        try {
          indexes.push_back(std::stoll(inner.substr(start, comma - start)));
        } catch (...) {
          if (error) *error = fmt::format("'{}': the index is not a number", path);
          return std::nullopt;
        }
        start = comma + 1;
      }
      const uint64_t element = layouts.of(type->element).size;
      uint64_t offset = 0;
      for (size_t d = 0; d < type->dimensions.size() && d < indexes.size(); ++d) {
        const auto& dim = type->dimensions[d];
        if (indexes[d] < dim.lower || indexes[d] > dim.upper) {
          if (error) *error = fmt::format("'{}': index {} is outside {}..{}", path, indexes[d], dim.lower, dim.upper);
          return std::nullopt;
        }
        uint64_t stride = element;
        for (size_t later = d + 1; later < type->dimensions.size(); ++later) {
          stride *= static_cast<uint64_t>(type->dimensions[later].upper - type->dimensions[later].lower + 1);
        }
        offset += static_cast<uint64_t>(indexes[d] - dim.lower) * stride;
      }
      ref = ValueRef{type->element, ref->address + offset};
      continue;
    }
    bool found = false;
    for (const check::Symbol* member : members_of(layouts, type)) {
      if (!check::names_equal(member->name, part)) continue;
      VariableView view{std::string(member->name), member->type, ref->address + layouts.offset(member),
                        Layouts::held_by_reference(member)};
      ref = variable_ref(machine, view);
      found = true;
      break;
    }
    if (!found && type->kind == check::TypeKind::Pou) {
      if (auto flag = sfc_flag(layouts, type->declaration, ref->address, parts, next)) {
        ref = flag;
        ++next;
        continue;
      }
    }
    if (!found) {
      if (error) *error = fmt::format("'{}': there is no member '{}'", path, part);
      return std::nullopt;
    }
  }
  return ref;
}

bool write_value(const CompiledProject& project, Machine& machine, const ValueRef& ref, std::string_view raw,
                 std::string* error) {
  Layouts& layouts = layouts_of(project);
  const check::Type* type = strip(ref.type);
  std::string text(raw);
  while (!text.empty() && text.back() == ' ') text.pop_back();
  while (!text.empty() && text.front() == ' ') text.erase(text.begin());
  auto fail = [&](std::string why) {
    if (error) *error = std::move(why);
    return false;
  };
  if (!type) return fail("unknown type");
  const TypeLayout layout = layouts.of(type);
  if (!machine.valid(ref.address, layout.size)) return fail("the variable is outside the PLC's memory");
  uint8_t* at = machine.memory() + ref.address;
  using check::TypeKind;
  if (type->kind == TypeKind::String || type->kind == TypeKind::WString) {
    std::string content = text;
    if (content.size() >= 2 && (content.front() == '\'' || content.front() == '"')) {
      auto parsed = check::parse_string_literal(content);
      if (!parsed) return fail(fmt::format("'{}' is not a string literal", text));
      content = *parsed;
    }
    const bool wide = type->kind == TypeKind::WString;
    std::string bytes = wide ? utf8_to_utf16le(content) : utf8_to_single_byte(content);
    const size_t unit = wide ? 2 : 1;
    bytes.resize(std::min<size_t>(bytes.size(), type->length * unit));
    std::copy(bytes.begin(), bytes.end(), at);
    std::fill(at + bytes.size(), at + bytes.size() + unit, uint8_t{0});
    return true;
  }
  const Scalar scalar = Layouts::scalar_of(type);
  if (scalar == Scalar::None) return fail("only elementary variables can be set");
  Slot slot{};
  if (type->kind == TypeKind::Bool) {
    if (check::names_equal(text, "TRUE") || text == "1") {
      slot.u = 1;
    } else if (check::names_equal(text, "FALSE") || text == "0") {
      slot.u = 0;
    } else {
      return fail(fmt::format("'{}' is not a BOOL (TRUE or FALSE)", text));
    }
  } else if (scalar == Scalar::F32 || scalar == Scalar::F64) {
    auto number = check::parse_real_literal(text);
    if (!number) {
      if (auto integer = check::parse_integer_literal(text.front() == '-' ? text.substr(1) : text)) {
        number = static_cast<double>(*integer) * (text.front() == '-' ? -1 : 1);
      }
    }
    if (!number) {
      try {
        number = std::stod(text);
      } catch (...) {
        return fail(fmt::format("'{}' is not a number", text));
      }
    }
    if (scalar == Scalar::F32) {
      slot.f32 = static_cast<float>(*number);
    } else {
      slot.f64 = *number;
    }
  } else if (type->kind == TypeKind::Duration) {
    auto ns = check::parse_duration_literal(text.find('#') == std::string::npos ? "T#" + text : text);
    if (!ns) return fail(fmt::format("'{}' is not a duration (T#1s500ms)", text));
    slot.i = type->long_variant ? static_cast<int64_t>(*ns) : static_cast<int64_t>(*ns / 1'000'000);
  } else if (type->kind == TypeKind::Date || type->kind == TypeKind::TimeOfDay || type->kind == TypeKind::DateTime) {
    const PointKind kind = type->kind == TypeKind::Date        ? PointKind::Date
                           : type->kind == TypeKind::TimeOfDay ? PointKind::TimeOfDay
                                                               : PointKind::DateAndTime;
    auto value = parse_point_literal(text, kind, time_unit_of(type));
    if (!value) return fail(fmt::format("'{}' is not a {}", text, type->name));
    slot.i = *value;
  } else {
    bool found = false;
    if (type->kind == TypeKind::Enum && type->declaration) {
      std::string name = text;
      if (const size_t hash = name.find('#'); hash != std::string::npos) name = name.substr(hash + 1);
      for (const check::Symbol* member : type->declaration->ordered) {
        if (member->kind == check::SymbolKind::EnumValue && check::names_equal(member->name, name)) {
          slot.i = static_cast<int64_t>(layouts.model().enum_value(member).value_or(0));
          found = true;
        }
      }
    }
    if (!found) {
      const bool negative = !text.empty() && text.front() == '-';
      auto number = check::parse_integer_literal(negative ? text.substr(1) : text);
      if (!number) return fail(fmt::format("'{}' is not a number", text));
      slot.i = static_cast<int64_t>(negative ? -*number : *number);
      const auto range = check::integer_range(type->kind == TypeKind::Enum && type->element ? type->element : type);
      const __int128 value = negative ? -*number : *number;
      if (range && (value < range->lower || value > range->upper)) {
        return fail(fmt::format("{} does not fit in {}", text, type->name));
      }
    }
  }
  if (ref.bit >= 0) {
    const auto mask = static_cast<uint8_t>(1u << ref.bit);
    *at = static_cast<uint8_t>(slot.u != 0 ? (*at | mask) : (*at & ~mask));
    return true;
  }
  switch (scalar) {
    case Scalar::U8:
    case Scalar::S8: { const auto v = static_cast<uint8_t>(slot.u); std::memcpy(at, &v, 1); break; }
    case Scalar::U16:
    case Scalar::S16: { const auto v = static_cast<uint16_t>(slot.u); std::memcpy(at, &v, 2); break; }
    case Scalar::U32:
    case Scalar::S32: { const auto v = static_cast<uint32_t>(slot.u); std::memcpy(at, &v, 4); break; }
    case Scalar::F32: std::memcpy(at, &slot.f32, 4); break;
    case Scalar::F64: std::memcpy(at, &slot.f64, 8); break;
    default: std::memcpy(at, &slot.u, 8); break;
  }
  return true;
}

}  // namespace rung::run
