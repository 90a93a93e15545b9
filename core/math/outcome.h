// Errors as values: a computation returns its value or an Error that names the field
// (or grid point) and the reason. Failure is explicit; nothing throws across the core.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace hobsharp {

// What kind of failure an Error is: a refused input (the engineer changes a field), valid input
// whose equations have no solution (a grid point the wheel never grinds, no contact), or a fault
// of the calculator itself (the binding layer's report of a caught exception or a non-finite result).
enum class ErrorCode { InvalidInput, Unsolvable, Internal };

struct Error {
  std::string field;    // the input field, e.g. "hob.pitchDiameter", or "grid" for a grid point
  std::string message;  // a whole sentence for the engineer, naming the field and the reason
  ErrorCode code = ErrorCode::InvalidInput;
};

// The usual refusal: the message begins with the field's name ("hob.gashDepth: must be ...").
inline Error refuse(const std::string& field, const std::string& reason,
                    ErrorCode code = ErrorCode::InvalidInput) {
  return Error{field, field + ": " + reason, code};
}

template <class T>
class Outcome {
 public:
  Outcome(T value) : state_(std::move(value)) {}        // NOLINT: implicit on purpose
  Outcome(Error error) : state_(std::move(error)) {}    // NOLINT: implicit on purpose

  bool ok() const { return std::holds_alternative<T>(state_); }
  explicit operator bool() const { return ok(); }

  const T& value() const& { return std::get<T>(state_); }
  T& value() & { return std::get<T>(state_); }
  T&& value() && { return std::get<T>(std::move(state_)); }
  const T* operator->() const { return &std::get<T>(state_); }
  const T& operator*() const { return std::get<T>(state_); }

  const Error& error() const { return std::get<Error>(state_); }

 private:
  std::variant<T, Error> state_;
};

// A check or a step that has no value: it succeeded, or it holds the Error.
template <>
class Outcome<void> {
 public:
  Outcome() = default;                                // success
  Outcome(Error error) : error_(std::move(error)) {}  // NOLINT: implicit on purpose

  bool ok() const { return !error_.has_value(); }
  explicit operator bool() const { return ok(); }

  const Error& error() const { return *error_; }

 private:
  std::optional<Error> error_;
};

inline Outcome<void> success() { return Outcome<void>(); }

}  // namespace hobsharp
