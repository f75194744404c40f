#include "program/source_errors.hpp"

#include <utility>

namespace ncsim::program {

void SourceErrors::not_supported(std::uint32_t line, const std::string& what) {
  raise_in(file_, line, kNotSupportedId, "not supported: " + what);
}

void SourceErrors::raise(std::uint32_t line, const std::string& id, const std::string& what) {
  raise_in(file_, line, id, what);
}

void SourceErrors::raise_in(std::uint16_t file, std::uint32_t line, const std::string& id,
                            const std::string& what) {
  core::Diagnostic d;
  d.file = interp_.file_name(file);
  d.loc = {line, 1};
  d.id = id;
  d.message = what;
  error_ = d;
  throw Stop{};
}

void SourceErrors::defer() noexcept {
  deferred_ = std::move(error_);
  error_.reset();
}

void SourceErrors::raise_deferred() {
  if (!deferred_) return;
  error_ = std::move(deferred_);
  deferred_.reset();
  throw Stop{};
}

}  // namespace ncsim::program
