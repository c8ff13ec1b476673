#include "parser/containers/container_document.hpp"

#include <algorithm>

namespace rung::containers {

std::string_view container_kind_name(ContainerKind kind) {
  switch (kind) {
    case ContainerKind::None: return "none";
    case ContainerKind::TwinCat: return "twincat";
    case ContainerKind::CodesysExp: return "codesys-exp";
    case ContainerKind::PlcOpen: return "plcopen";
    case ContainerKind::Unsupported: return "unsupported";
  }
  return "none";
}

const Segment* ContainerDocument::segment_at(uint32_t virtual_offset) const {
  const auto after = std::upper_bound(segments.begin(), segments.end(), virtual_offset,
                                      [](uint32_t v, const Segment& s) { return v < s.virtual_begin; });
  if (after == segments.begin()) return nullptr;
  const Segment& s = *(after - 1);
  if (virtual_offset >= s.virtual_begin + s.length) return nullptr;
  return &s;
}

std::optional<uint32_t> ContainerDocument::to_file_offset(uint32_t virtual_offset) const {
  if (segments.empty()) return std::nullopt;
  const auto real_end = [](const Segment& s) { return *s.file_begin + s.length; };
  if (virtual_offset >= virtual_text.size()) {
    for (auto it = segments.rbegin(); it != segments.rend(); ++it) {
      if (it->file_begin) return real_end(*it);
    }
    return std::nullopt;
  }
  const Segment* hit = segment_at(virtual_offset);
  if (hit == nullptr) return std::nullopt;
  if (hit->file_begin) return *hit->file_begin + (virtual_offset - hit->virtual_begin);

  // Synthetic: look for the nearest real neighbour (usually the very next segment).
  const auto index = static_cast<size_t>(hit - segments.data());
  for (size_t i = index + 1; i < segments.size(); ++i) {
    if (segments[i].file_begin) return *segments[i].file_begin;
  }
  for (size_t i = index; i-- > 0;) {
    if (segments[i].file_begin) return real_end(segments[i]);
  }
  return std::nullopt;
}

void ContainerDocument::build_index() {
  by_file_.clear();
  for (size_t i = 0; i < segments.size(); ++i) {
    if (segments[i].file_begin) by_file_.push_back(static_cast<uint32_t>(i));
  }
  std::stable_sort(by_file_.begin(), by_file_.end(),
                   [&](uint32_t a, uint32_t b) { return *segments[a].file_begin < *segments[b].file_begin; });
  indexed_segments_ = segments.size();
}

std::optional<uint32_t> ContainerDocument::to_virtual_offset(uint32_t file_offset) const {
  const auto map = [&](const Segment& s) -> std::optional<uint32_t> {
    if (!s.file_begin || file_offset < *s.file_begin || file_offset > *s.file_begin + s.length) return std::nullopt;
    return s.virtual_begin + (file_offset - *s.file_begin);
  };
  if (indexed_segments_ != segments.size()) {
    for (const Segment& s : segments) {
      if (const auto v = map(s)) return v;
    }
    return std::nullopt;
  }
  // The last segment starting at or before the offset; if the offset is exactly
  // the end of one segment and the start of the next, the next one wins.
  const auto after = std::upper_bound(by_file_.begin(), by_file_.end(), file_offset,
                                      [&](uint32_t f, uint32_t i) { return f < *segments[i].file_begin; });
  if (after == by_file_.begin()) return std::nullopt;
  return map(segments[*(after - 1)]);
}

void VirtualTextBuilder::append_real(std::string_view text, uint32_t file_begin, std::string_view role,
                                     std::string_view object_name) {
  append(text, file_begin, role, object_name);
}

void VirtualTextBuilder::append_synthetic(std::string_view text, std::string_view role, std::string_view object_name) {
  append(text, std::nullopt, role, object_name);
}

void VirtualTextBuilder::append(std::string_view text, std::optional<uint32_t> file_begin, std::string_view role,
                                std::string_view object_name) {
  if (text.empty()) return;
  auto& segments = doc_.segments;
  const auto begin = static_cast<uint32_t>(doc_.virtual_text.size());
  doc_.virtual_text.append(text);
  if (!segments.empty()) {
    Segment& last = segments.back();
    const bool same_owner = last.role == role && last.object_name == object_name;
    const bool both_synthetic = !last.file_begin && !file_begin;
    const bool contiguous = last.file_begin && file_begin && *last.file_begin + last.length == *file_begin;
    if (same_owner && (both_synthetic || contiguous)) {
      last.length += static_cast<uint32_t>(text.size());
      return;
    }
  }
  segments.push_back(
      {begin, static_cast<uint32_t>(text.size()), file_begin, std::string(role), std::string(object_name)});
}

ContainerDocument VirtualTextBuilder::finish(ContainerKind kind) {
  ContainerDocument doc = std::move(doc_);
  doc_ = ContainerDocument{};
  doc.kind = kind;
  doc.build_index();
  return doc;
}

ContainerDocument plain_document(std::string_view text, ContainerKind kind) {
  VirtualTextBuilder builder;
  builder.append_real(text, 0, "file", "");
  return builder.finish(kind);
}

}  // namespace rung::containers
