#pragma once
/// Wall-clock timing of one pipeline stage.

#include <chrono>

namespace resharp {

/// Measures the wall time since construction (steady clock).
class StageTimer {
public:
    StageTimer() : start_(std::chrono::steady_clock::now()) {}
    std::chrono::nanoseconds elapsed() const {
        return std::chrono::duration_cast<std::chrono::nanoseconds>(
            std::chrono::steady_clock::now() - start_);
    }

private:
    std::chrono::steady_clock::time_point start_;
};

}  // namespace resharp
