#include "resharp/eval/position_index.h"

#include <functional>

namespace resharp::eval {

std::size_t PositionIndex::KeyHash::operator()(const Key& k) const {
    std::size_t h = 0;
    for (float f : k.c) h = h * 1000003u ^ std::hash<float>()(f);
    return h;
}

PositionIndex::Key PositionIndex::key_of(const Vec3& p) {
    return {{static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())}};
}

PositionIndex::PositionIndex(std::span<const Vec3> points) {
    index_.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) index_.emplace(key_of(points[i]), Index(i));
}

std::optional<Index> PositionIndex::find(const Vec3& p) const {
    const auto it = index_.find(key_of(p));
    if (it == index_.end()) return std::nullopt;
    return it->second;
}

}  // namespace resharp::eval
