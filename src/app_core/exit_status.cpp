#include "app_core/exit_status.h"

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
        return {exit_out_of_memory, out_of_memory_message};
    } catch (const std::exception& e) {
        return {exit_failure, e.what()};
    } catch (...) {
        return {exit_failure, "unknown error"};
    }
}

}  // namespace cutaway::app
