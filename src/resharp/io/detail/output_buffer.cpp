#include "resharp/io/detail/output_buffer.h"

#include <array>
#include <charconv>

namespace resharp::io::detail {

OutputBuffer::OutputBuffer(std::ostream& out) : out_(out) { pending_.reserve(kBlock + 64); }

OutputBuffer::~OutputBuffer() { flush(); }

template <class T>
void OutputBuffer::append_chars(T value) {
    std::array<char, 32> chars;  // shortest double is at most 24 characters
    const auto result = std::to_chars(chars.data(), chars.data() + chars.size(), value);
    pending_.append(chars.data(), result.ptr);
    flush_if_full();
}

void OutputBuffer::number(double value) { append_chars(value); }
void OutputBuffer::number(float value) { append_chars(value); }
void OutputBuffer::number(std::int64_t value) { append_chars(value); }

void OutputBuffer::flush() {
    if (pending_.empty()) return;
    out_.write(pending_.data(), static_cast<std::streamsize>(pending_.size()));
    pending_.clear();
}

}  // namespace resharp::io::detail
