#pragma once
// The part of a job that belongs to one machine module alone. The first two machines keep their
// fields in Job itself (history); every later machine keeps its own struct here, derived from
// MachineSpec, so that Job does not grow with every machine and nothing outside the module needs
// to know the struct. A Job stays a value: copying it copies the spec (clone()).
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

namespace cutcell {

struct MachineSpec {
    virtual ~MachineSpec() = default;
    virtual std::unique_ptr<MachineSpec> clone() const = 0;
};

// Helper for a spec struct: `struct SawSpec : MachineSpecOf<SawSpec> { ... };`
template <class Derived> struct MachineSpecOf : MachineSpec {
    std::unique_ptr<MachineSpec> clone() const override {
        return std::make_unique<Derived>(static_cast<const Derived&>(*this));
    }
};

// Value-semantic holder of a MachineSpec (deep copy).
class MachineSpecHolder {
  public:
    MachineSpecHolder() = default;
    explicit MachineSpecHolder(std::unique_ptr<MachineSpec> spec) : spec_(std::move(spec)) {}
    MachineSpecHolder(const MachineSpecHolder& o) : spec_(o.spec_ ? o.spec_->clone() : nullptr) {}
    MachineSpecHolder(MachineSpecHolder&&) noexcept = default;
    MachineSpecHolder& operator=(const MachineSpecHolder& o) {
        if (this != &o) spec_ = o.spec_ ? o.spec_->clone() : nullptr;
        return *this;
    }
    MachineSpecHolder& operator=(MachineSpecHolder&&) noexcept = default;

    template <class T> void set(T value) { spec_ = std::make_unique<T>(std::move(value)); }
    // The spec as T, or nullptr when the job holds none or another machine's.
    template <class T> const T* as() const { return dynamic_cast<const T*>(spec_.get()); }
    template <class T> T* as() { return dynamic_cast<T*>(spec_.get()); }
    bool empty() const { return !spec_; }

  private:
    std::unique_ptr<MachineSpec> spec_;
};

// A machine's section of a job as T, for the machine's accessor (pipeRobotSpec(job), ...): a
// holder with no section yet (a job being built in code) reads as T's defaults, and editSpec
// gives it one to edit; a holder with another machine's section throws std::invalid_argument
// (`whose`: "the pipe robot's").
template <class T> const T& readSpec(const MachineSpecHolder& h, const char* whose) {
    static const T defaults;
    if (h.empty()) return defaults;
    if (const T* s = h.as<T>()) return *s;
    throw std::invalid_argument(std::string("the job holds another machine's section, not ") +
                                whose);
}
template <class T> T& editSpec(MachineSpecHolder& h, const char* whose) {
    if (h.empty()) h.set(T{});
    if (T* s = h.as<T>()) return *s;
    throw std::invalid_argument(std::string("the job holds another machine's section, not ") +
                                whose);
}

} // namespace cutcell
