/*
 * Takes the address of every entry point the headers in include/ declare, and checks that
 * each one resolves to a non-null address in the linked library.
 *
 * The list comes from build.rs ($OUT_DIR/entry_points.inc, one EP(name) per function);
 * extension functions sit under #if defined(GL_GLEXT_PROTOTYPES) or
 * defined(EGL_EGLEXT_PROTOTYPES), so this file compiles with and without those macros.
 * tests/headers.rs builds it as C99, C11 and C++11 with -Wall -Wextra -Werror -pedantic.
 *
 * ct:headers-only (tests/headers.rs builds it; the C program harness skips it)
 *
 * Prints "entry points: N" and exits 0 when every address is non-null.
 */

#include <GLES/gl.h>
#include <GLES/glext.h>
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <stdio.h>

typedef void (*any_function)(void);

struct entry_point {
    const char *name;
    any_function address;
};

#define EP(name) {#name, (any_function)(name)},

static const struct entry_point entry_points[] = {
#include "entry_points.inc"
    {NULL, NULL} /* keeps the array non-empty */
};

int main(void)
{
    size_t i;
    size_t count = 0;
    int failures = 0;

    for (i = 0; entry_points[i].name != NULL; ++i) {
        ++count;
        if (entry_points[i].address == NULL) {
            printf("null address: %s\n", entry_points[i].name);
            ++failures;
        }
    }
    printf("entry points: %lu\n", (unsigned long)count);
    return failures == 0 ? 0 : 1;
}
