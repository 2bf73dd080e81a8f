#pragma once
/// A vector that keeps its first N elements inline, so the common short list (a dexel ray with
/// one or two solid intervals) costs no heap allocation.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace resharp::sim {

/// Holds up to N elements inline and spills to a heap vector beyond that. Only whole-list
/// assignment is offered: the simulator rebuilds a ray's list in a scratch buffer and assigns it.
template <class T, std::size_t N>
class SmallVector {
public:
    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }

    const T* data() const { return size_ <= N ? inline_.data() : heap_.data(); }
    const T* begin() const { return data(); }
    const T* end() const { return data() + size_; }
    const T& operator[](std::size_t i) const { return data()[i]; }
    const T& front() const { return data()[0]; }
    const T& back() const { return data()[size_ - 1]; }

    /// Replaces the contents with [first, last); the range must not alias this vector.
    void assign(const T* first, const T* last) {
        const auto count = static_cast<std::size_t>(last - first);
        if (count <= N) {
            std::copy(first, last, inline_.begin());
            heap_.clear();  // keep the capacity: a ray that spilled once tends to spill again
        } else {
            heap_.assign(first, last);
        }
        size_ = static_cast<std::uint32_t>(count);
    }

private:
    std::array<T, N> inline_{};
    std::vector<T> heap_;
    std::uint32_t size_ = 0;
};

}  // namespace resharp::sim
