#include "resharp/eval/position_index.h"

#include <functional>

namespace resharp::eval {

template <class T>
std::size_t PositionIndex::KeyHash::operator()(const Key<T>& k) const {
    std::size_t h = 0;
    for (T f : k.c) h = h * 1000003u ^ std::hash<T>()(f);
    return h;
}

PositionIndex::PositionIndex(std::span<const Vec3> points) {
    exact_.reserve(points.size());
    rounded_.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        exact_.emplace(key_of<double>(points[i]), Index(i));
        rounded_.emplace(key_of<float>(points[i]), Index(i));
    }
}

std::optional<Index> PositionIndex::find(const Vec3& p) const {
    if (const auto it = exact_.find(key_of<double>(p)); it != exact_.end()) return it->second;
    if (const auto it = rounded_.find(key_of<float>(p)); it != rounded_.end()) return it->second;
    return std::nullopt;
}

}  // namespace resharp::eval
