// User errors: bad scene keys, values, formulas and paths. They carry the key (or what was bad)
// and a one-line message, are thrown by the library and caught once at the boundary (the CLI's
// main, which prints the message and exits with code 2; the server answers 400). Invariant
// violations are not user errors; they are checked with assertions in tests.
#pragma once

#include <stdexcept>
#include <string>

namespace quaternia {

class UserError : public std::runtime_error {
  public:
    // `key` names what was bad, e.g. "render.width", "fractal.formula" or an output path.
    UserError(std::string key, const std::string& message)
        : std::runtime_error(message), key_(std::move(key)) {}
    const std::string& key() const { return key_; }

  private:
    std::string key_;
};

// A request that does not fit its memory budget (memory_budget.h, requireMemory), refused before
// the work: a UserError that front ends may tell apart (Python raises MemoryError).
class MemoryLimitError : public UserError {
  public:
    using UserError::UserError;
};

}  // namespace quaternia
