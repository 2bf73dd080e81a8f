#include "fuzz_reader.h"
#include "resharp/io/off.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return resharp::fuzz::run(data, size, [](std::string_view bytes) {
        return resharp::io::read_off(bytes, "fuzz.off");
    });
}
