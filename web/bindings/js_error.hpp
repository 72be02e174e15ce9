// carom web: library errors as JavaScript errors. A bound function that lets a C++ exception
// escape gives JavaScript only a pointer; through guarded() the page gets an Error whose message
// is carom::InvalidArgument's own ("carom::FUNCTION: ARGUMENT = VALUE: REQUIREMENT").
#pragma once

#include <exception>
#include <string>
#include <utility>

namespace carom::web {

// Raises a JavaScript Error with this message in the calling page. Never returns.
[[noreturn]] void throw_js_error(const std::string& message);

// Calls fn(args...), turning any std::exception into a JavaScript Error.
template <typename Fn, typename... Args>
decltype(auto) guarded_call(Fn&& fn, Args&&... args) {
  try {
    return std::forward<Fn>(fn)(std::forward<Args>(args)...);
  } catch (const std::exception& error) {
    throw_js_error(error.what());
  }
}

// guarded<&f>::call has f's signature and calls f through guarded_call, so that embind can bind
// it as a plain function pointer.
template <auto Fn>
struct guarded;

template <typename R, typename... Args, R (*Fn)(Args...)>
struct guarded<Fn> {
  static R call(Args... args) { return guarded_call(Fn, std::forward<Args>(args)...); }
};

}  // namespace carom::web
