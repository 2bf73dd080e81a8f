#include "exit_status.h"

#include <exception>
#include <new>

#include "commands.h"
#include "resharp/core/errors.h"

namespace resharp::cli {

Failure current_failure() {
    try {
        throw;
    } catch (const ReadError& e) {  // includes ParseError
        return {kBadInput, e.what()};
    } catch (const InvalidInput& e) {
        return {kBadInput, e.what()};
    } catch (const WriteError& e) {
        return {kOutputFailed, e.what()};
    } catch (const std::bad_alloc&) {
        return {kInternalError, "out of memory"};
    } catch (const std::exception& e) {
        return {kInternalError, e.what()};
    } catch (...) {
        return {kInternalError, "unknown error"};
    }
}

}  // namespace resharp::cli
