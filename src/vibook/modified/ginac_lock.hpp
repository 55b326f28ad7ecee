/// \file ginac_lock.hpp
/// \brief One lock for every use of GiNaC, and two ways to keep GiNaC objects beside other
/// threads: ginac_shared (a shared, read-only copy) and GinacGuarded (a class's own members).
///
/// GiNaC is not thread-safe: the reference counts of its objects, the shared constants 0 and 1
/// included, are not atomic, so two threads that make, copy or destroy any GiNaC objects at
/// the same time can corrupt a count and free an object still in use. `vibook claims` runs the
/// checks in parallel, and the field audit's rows run in parallel inside one check: every GiNaC
/// object that may exist beside another thread's is made, copied and destroyed with
/// ginac_mutex() held. The `tsan` build preset (ThreadSanitizer) finds a use outside it.
#pragma once

#include <memory>
#include <mutex>
#include <utility>

namespace vibook::modified {

/// The lock of every GiNaC use. Recursive, so that an object kept by ginac_shared or
/// GinacGuarded may be copied or released with the lock already held.
std::recursive_mutex& ginac_mutex();

/// `value` kept for later use beside other threads: a shared_ptr (whose copies are atomic) to
/// an object moved in under ginac_mutex() and destroyed under it when the last owner lets go.
/// The way a std::function that outlives its maker (a study's hook) keeps GiNaC objects.
/// Call with the lock held (the argument is itself a GiNaC object); reading the object takes
/// it too.
template <class T>
std::shared_ptr<const T> ginac_shared(T value) {
  const std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  return std::shared_ptr<const T>(new T(std::move(value)), [](const T* p) {
    const std::lock_guard<std::recursive_mutex> relock(ginac_mutex());
    delete p;
  });
}

/// A base for a class whose members hold GiNaC objects: `Storage` (a struct of those members,
/// the GiNaC objects inside containers, so that a moved-from Storage holds none) is copied,
/// moved, assigned and destroyed with ginac_mutex() held. The class's own code that makes or
/// reads GiNaC objects still takes the lock.
template <class Storage>
class GinacGuarded : protected Storage {
 protected:
  GinacGuarded() = default;
  GinacGuarded(const GinacGuarded& other) : Storage(copy(other)) {}
  GinacGuarded(GinacGuarded&& other) : Storage(take(std::move(other))) {}
  GinacGuarded& operator=(const GinacGuarded& other) {
    const std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
    Storage::operator=(other);
    return *this;
  }
  GinacGuarded& operator=(GinacGuarded&& other) {
    const std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
    Storage::operator=(std::move(other));
    return *this;
  }
  ~GinacGuarded() {
    const std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
    const Storage gone(std::move(static_cast<Storage&>(*this)));  // destroyed here, locked
  }

 private:
  static Storage copy(const Storage& s) {
    const std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
    return s;
  }
  static Storage take(Storage&& s) {
    const std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
    return std::move(s);
  }
};

}  // namespace vibook::modified
