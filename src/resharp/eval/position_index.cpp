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
    // Only a point a float holds may have lost digits to one: a point that needs a double came
    // from a file that keeps doubles, so its match, if any, is exact (a restored point a few
    // micrometres from an input vertex is not that vertex).
    const Key<float> rounded = key_of<float>(p);
    if (Vec3(rounded.c[0], rounded.c[1], rounded.c[2]) != p) return std::nullopt;
    if (const auto it = rounded_.find(rounded); it != rounded_.end()) return it->second;
    return std::nullopt;
}

}  // namespace resharp::eval
