#include "app/exit_status.h"

#include <new>
#include <stdexcept>

#include "gl/gl_error.h"
#include "io/bad_input_error.h"

namespace cutaway::app {

ExitStatus exit_status_of(const std::exception_ptr& error) {
    try {
        std::rethrow_exception(error);
    } catch (const io::BadInputError& e) {
        return {exit_bad_input, e.what()};
    } catch (const std::invalid_argument& e) {
        return {exit_bad_input, e.what()};
    } catch (const gl::GlError& e) {
        return {exit_gl_failure, std::string("OpenGL: ") + e.what()};
    } catch (const std::bad_alloc&) {
        // Budgets are checked before large allocations (--memory-limit-gb), so this is the machine
        // (or an address-space limit) running out below the budget.
        return {exit_out_of_memory,
                "out of memory below the --memory-limit-gb budget: lower --memory-limit-gb to what this machine "
                "(or its ulimit -v) can give, or use a smaller model or image"};
    } catch (const std::exception& e) {
        return {exit_failure, e.what()};
    } catch (...) {
        return {exit_failure, "unknown error"};
    }
}

}  // namespace cutaway::app
