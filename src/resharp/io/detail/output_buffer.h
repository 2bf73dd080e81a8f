#pragma once
/// Internal to resharp::io: the shared back end of every writer. Formats numbers with
/// std::to_chars (shortest text that reads back to the same value, independent of locale, so
/// output is byte-deterministic) and hands the stream large blocks instead of many small writes.

#include <bit>
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>

#include "resharp/io/detail/byte_cursor.h"

namespace resharp::io::detail {

class OutputBuffer {
public:
    explicit OutputBuffer(std::ostream& out);
    OutputBuffer(const OutputBuffer&) = delete;
    OutputBuffer& operator=(const OutputBuffer&) = delete;
    /// Hands any pending bytes to the stream.
    ~OutputBuffer();

    void text(std::string_view s) {
        pending_.append(s);
        flush_if_full();
    }
    void text(char c) { pending_.push_back(c); }
    /// Shortest decimal form that reads back as exactly `value`.
    void number(double value);
    void number(float value);
    void number(std::int64_t value);
    /// `value` in little-endian byte order.
    template <class T>
    void binary(T value) {
        auto raw = std::bit_cast<SameSizeUnsigned<T>>(value);
        if constexpr (std::endian::native == std::endian::big) raw = byte_swapped(raw);
        pending_.append(reinterpret_cast<const char*>(&raw), sizeof(raw));
        flush_if_full();
    }
    /// Writes pending bytes to the stream. Failures show in the stream's state.
    void flush();

private:
    void flush_if_full() {
        if (pending_.size() >= kBlock) flush();
    }
    template <class T>
    void append_chars(T value);

    static constexpr std::size_t kBlock = 1 << 20;
    std::ostream& out_;
    std::string pending_;
};

}  // namespace resharp::io::detail
