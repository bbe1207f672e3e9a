#pragma once
// The compiled catalogues (po/<tag>.po through msgfmt), embedded in the binary at build time by
// cmake/EmbedCatalogs.cmake.
#include <cstdint>
#include <span>
#include <string_view>

namespace collide::text::detail {

struct EmbeddedCatalog {
  std::string_view tag;  // from the file name: po/pt_BR.po -> "pt-BR"
  std::span<const std::uint8_t> mo_bytes;
};

// In tag order.
std::span<const EmbeddedCatalog> embeddedCatalogs();

}  // namespace collide::text::detail
