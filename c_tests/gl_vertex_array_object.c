/*
 * gl_vertex_array_object.c: GL_OES_vertex_array_object: each object keeps its own array
 * pointers, enables and element buffer; the ARRAY_BUFFER binding and the current color stay
 * the context's; names must come from glGenVertexArraysOES; deleting the bound object binds
 * the default one.
 * ct:no-diff (Mesa 22 lists the extension for ES 1 too, but there its entry points do
 * nothing: glGenVertexArraysOES returns no names)
 */
#include "common.h"

/* Extension functions through eglGetProcAddress (Mesa exports them only that way). */
static PFNGLGENVERTEXARRAYSOESPROC glGenVertexArraysOES;
static PFNGLBINDVERTEXARRAYOESPROC glBindVertexArrayOES;
static PFNGLDELETEVERTEXARRAYSOESPROC glDeleteVertexArraysOES;
static PFNGLISVERTEXARRAYOESPROC glIsVertexArrayOES;

static GLint integer(GLenum pname)
{
    GLint v = -1;
    glGetIntegerv(pname, &v);
    return v;
}

int main(void)
{
    static const GLfloat left[] = {-1, -1, 0, -1, -1, 1, 0, 1};
    static const GLfloat right[] = {0, -1, 1, -1, 0, 1, 1, 1};
    static const GLubyte strip[] = {0, 1, 2, 3};
    GLuint vao[2], eb, ab;

    ct_init(8, 8);
    glGenVertexArraysOES = (PFNGLGENVERTEXARRAYSOESPROC)eglGetProcAddress("glGenVertexArraysOES");
    glBindVertexArrayOES = (PFNGLBINDVERTEXARRAYOESPROC)eglGetProcAddress("glBindVertexArrayOES");
    glDeleteVertexArraysOES =
        (PFNGLDELETEVERTEXARRAYSOESPROC)eglGetProcAddress("glDeleteVertexArraysOES");
    glIsVertexArrayOES = (PFNGLISVERTEXARRAYOESPROC)eglGetProcAddress("glIsVertexArrayOES");
    CHECK(glGenVertexArraysOES && glBindVertexArrayOES && glDeleteVertexArraysOES &&
          glIsVertexArrayOES);
    if (!glGenVertexArraysOES || !glBindVertexArrayOES || !glDeleteVertexArraysOES ||
        !glIsVertexArrayOES)
        return ct_done();
    CHECK(strstr((const char *)glGetString(GL_EXTENSIONS), "GL_OES_vertex_array_object") != NULL);

    glGenVertexArraysOES(2, vao);
    CHECK(vao[0] != 0 && vao[1] != 0 && vao[0] != vao[1]);
    CHECK(!glIsVertexArrayOES(vao[0])); /* an object only once bound */
    CHECK(integer(GL_VERTEX_ARRAY_BINDING_OES) == 0);

    glGenBuffers(1, &eb);
    glGenBuffers(1, &ab);
    glBindVertexArrayOES(vao[0]);
    CHECK(glIsVertexArrayOES(vao[0]));
    CHECK(integer(GL_VERTEX_ARRAY_BINDING_OES) == (GLint)vao[0]);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, left);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, eb);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof strip, strip, GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, ab); /* not part of the object */

    glBindVertexArrayOES(vao[1]);
    CHECK(!glIsEnabled(GL_VERTEX_ARRAY)); /* a new object starts with the defaults */
    CHECK(integer(GL_ELEMENT_ARRAY_BUFFER_BINDING) == 0);
    CHECK(integer(GL_ARRAY_BUFFER_BINDING) == (GLint)ab);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, right);
    CHECK_GL(GL_NO_ERROR);

    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor4f(1, 0, 0, 1);
    glBindVertexArrayOES(vao[0]);
    CHECK(integer(GL_ELEMENT_ARRAY_BUFFER_BINDING) == (GLint)eb);
    glDrawElements(GL_TRIANGLE_STRIP, 4, GL_UNSIGNED_BYTE, (const void *)0); /* from eb */
    CHECK_PIXEL(2, 4, 255, 0, 0, 255, 0);
    CHECK_PIXEL(6, 4, 0, 0, 0, 0, 0);
    glColor4f(0, 1, 0, 1);
    glBindVertexArrayOES(vao[1]);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    CHECK_PIXEL(2, 4, 255, 0, 0, 255, 0);
    CHECK_PIXEL(6, 4, 0, 255, 0, 255, 0);
    CHECK_GL(GL_NO_ERROR);

    /* The default object kept its own (disabled) arrays. */
    glBindVertexArrayOES(0);
    CHECK(!glIsEnabled(GL_VERTEX_ARRAY));
    CHECK(integer(GL_ELEMENT_ARRAY_BUFFER_BINDING) == 0);

    /* Errors: names not from glGenVertexArraysOES, negative counts. */
    glBindVertexArrayOES(vao[1] + 100);
    CHECK_GL(GL_INVALID_OPERATION);
    glGenVertexArraysOES(-1, vao);
    CHECK_GL(GL_INVALID_VALUE);
    glDeleteVertexArraysOES(-1, vao);
    CHECK_GL(GL_INVALID_VALUE);

    /* Deleting the bound object binds 0; its name is then gone. */
    glBindVertexArrayOES(vao[1]);
    glDeleteVertexArraysOES(2, vao);
    CHECK(integer(GL_VERTEX_ARRAY_BINDING_OES) == 0);
    CHECK(!glIsVertexArrayOES(vao[0]) && !glIsVertexArrayOES(vao[1]));
    glBindVertexArrayOES(vao[0]);
    CHECK_GL(GL_INVALID_OPERATION);
    glDeleteBuffers(1, &eb);
    glDeleteBuffers(1, &ab);
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
