#pragma once
/// Internal to resharp::io: a bounds-checked reader of binary numbers from a file held in
/// memory, shared by the binary STL and PLY readers. Every read checks the bytes left first and
/// throws ParseError naming the file and the byte offset.

#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>

namespace resharp::io::detail {

/// Reverses the bytes of an unsigned integer (std::byteswap is C++23).
template <class U>
constexpr U byte_swapped(U value) {
    U out = 0;
    for (std::size_t i = 0; i < sizeof(U); ++i) {
        out = static_cast<U>((out << 8) | (value & 0xff));
        value = static_cast<U>(value >> 8);
    }
    return out;
}

/// An unsigned integer type of the same size as T.
template <class T>
using SameSizeUnsigned = std::conditional_t<
    sizeof(T) == 1, std::uint8_t,
    std::conditional_t<sizeof(T) == 2, std::uint16_t,
                       std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;

/// The arithmetic value of type T stored at `bytes` in byte order `order`. No bounds check.
template <class T>
T load(const char* bytes, std::endian order) {
    using U = SameSizeUnsigned<T>;
    U raw;
    std::memcpy(&raw, bytes, sizeof(U));
    if (order != std::endian::native) raw = byte_swapped(raw);
    return std::bit_cast<T>(raw);
}

class ByteCursor {
public:
    /// `bytes` (the whole file) must outlive the cursor, which starts at byte `start`.
    ByteCursor(std::string_view bytes, const std::string& name, std::size_t start = 0)
        : bytes_(bytes), name_(name), pos_(start) {}

    std::size_t offset() const { return pos_; }
    std::size_t remaining() const { return bytes_.size() - pos_; }
    const std::string& name() const { return name_; }

    /// \throws ParseError at offset() unless `count` more bytes remain; `what` says what needed
    /// them.
    void require(std::size_t count, std::string_view what) const;

    /// The next `count` bytes, bounds checked.
    std::string_view take(std::size_t count, std::string_view what) {
        require(count, what);
        const std::string_view out = bytes_.substr(pos_, count);
        pos_ += count;
        return out;
    }

    /// The next value of type T in byte order `order`, bounds checked.
    template <class T>
    T read(std::endian order, std::string_view what) {
        return load<T>(take(sizeof(T), what).data(), order);
    }

    /// Throws ParseError at byte `offset`.
    [[noreturn]] void fail_at(std::size_t offset, const std::string& reason) const;
    /// Throws ParseError at offset().
    [[noreturn]] void fail(const std::string& reason) const { fail_at(pos_, reason); }

private:
    std::string_view bytes_;
    const std::string& name_;
    std::size_t pos_;
};

}  // namespace resharp::io::detail
