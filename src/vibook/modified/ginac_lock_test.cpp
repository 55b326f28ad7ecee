// Doctests of ginac_lock.hpp: GiNaC objects kept beside other threads are copied, moved and
// destroyed with modified::ginac_mutex() held. A probe member asks another thread whether the
// lock is free at the moment it is copied or destroyed (try_lock from there fails exactly when
// this thread holds it); a plain struct with the same probe, which takes no lock, must be seen
// doing so unlocked (the probe can fail).
#include <future>
#include <memory>
#include <mutex>
#include <vector>

#include <doctest/doctest.h>

#include "vibook/modified/ginac_lock.hpp"

using vibook::modified::ginac_mutex;
using vibook::modified::ginac_shared;
using vibook::modified::GinacGuarded;

namespace {

// Is ginac_mutex() held (by this thread) right now? Asked from another thread.
bool lock_held() {
  return !std::async(std::launch::async, [] {
            if (!ginac_mutex().try_lock()) return false;
            ginac_mutex().unlock();
            return true;
          }).get();
}

// Records, for each copy and destruction, whether the lock was held.
struct Probe {
  std::shared_ptr<std::vector<bool>> seen = std::make_shared<std::vector<bool>>();
  Probe() = default;
  Probe(const Probe& o) : seen(o.seen) { seen->push_back(lock_held()); }
  Probe& operator=(const Probe& o) {
    seen = o.seen;
    seen->push_back(lock_held());
    return *this;
  }
  ~Probe() {
    if (seen) seen->push_back(lock_held());
  }
};

struct Storage {
  std::vector<Probe> probes;  // in a container, as GinacGuarded asks
};

class Guarded : private GinacGuarded<Storage> {
 public:
  explicit Guarded(const Probe& p) {
    const std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
    probes.push_back(p);
  }
};

}  // namespace

TEST_CASE(
    "ginac lock: a guarded class copies, assigns and destroys its members with the lock held") {
  Probe p;
  const auto seen = p.seen;
  {
    Guarded a(p);
    Guarded b(a);  // a copy
    Guarded c(p);
    c = b;  // an assignment (c's old member destroyed, b's copied)
    Guarded d(std::move(b));
  }
  REQUIRE(seen->size() >= 6);
  for (std::size_t i = 0; i < seen->size(); ++i) {
    CAPTURE(i);
    CHECK((*seen)[i]);
  }
}

TEST_CASE(
    "ginac lock: ginac_shared destroys its value with the lock held, when the last owner lets go") {
  Probe p;
  const auto seen = p.seen;
  std::shared_ptr<const Storage> kept;
  {
    Storage s;
    const std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
    s.probes.push_back(p);
    kept = ginac_shared(std::move(s));
  }
  seen->clear();
  auto other = kept;  // a copy of the pointer: no copy of the value
  kept.reset();
  CHECK(seen->empty());
  other.reset();  // the last owner: the value is destroyed, locked
  REQUIRE(seen->size() == 1);
  CHECK(seen->front());
}

TEST_CASE("ginac lock: the probe sees a struct that takes no lock") {
  Probe p;
  const auto seen = p.seen;
  {
    const Storage plain{{p}};
    const Storage copy = plain;
  }
  REQUIRE(seen->size() >= 3);
  for (bool held : *seen) CHECK_FALSE(held);
}
