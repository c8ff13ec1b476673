#include "parser/containers/read_container.hpp"

#include "parser/containers/exp_reader.hpp"
#include "parser/containers/plcopen_reader.hpp"
#include "parser/containers/twincat_reader.hpp"

namespace rung::containers {

ContainerDocument read_container(ContainerKind kind, std::string_view /*path*/, std::string_view decoded_text) {
  switch (kind) {
    case ContainerKind::TwinCat: return read_twincat(decoded_text);
    case ContainerKind::CodesysExp: return read_exp(decoded_text);
    case ContainerKind::PlcOpen: return read_plcopen(decoded_text);
    case ContainerKind::Unsupported: {
      ContainerDocument doc;
      doc.kind = ContainerKind::Unsupported;
      return doc;
    }
    case ContainerKind::None: break;
  }
  return plain_document(decoded_text);
}

ContainerDocument read_container(std::string_view path, std::string_view decoded_text) {
  return read_container(detect_container(path, decoded_text), path, decoded_text);
}

}  // namespace rung::containers
