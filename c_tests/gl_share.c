/* Share groups: textures and buffers made in one context are visible, with their contents,
 * in a context created with it as share_context, and not in an unshared one. */
#include "common.h"

int main(void)
{
    static const GLfloat verts[] = {-1, -1, 1, -1, -1, 1, 1, 1};
    EGLContext shared, alone;
    GLuint tex = 0, buf = 0;
    GLint v = 0;

    ct_init(8, 8);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glGenBuffers(1, &buf);
    glBindBuffer(GL_ARRAY_BUFFER, buf);
    glBufferData(GL_ARRAY_BUFFER, sizeof verts, verts, GL_STATIC_DRAW);
    CHECK_GL(GL_NO_ERROR);

    shared = eglCreateContext(ct.display, ct.config, ct.context, NULL);
    alone = eglCreateContext(ct.display, ct.config, EGL_NO_CONTEXT, NULL);
    CHECK(shared != EGL_NO_CONTEXT && alone != EGL_NO_CONTEXT);

    CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, shared));
    CHECK(glIsTexture(tex) && glIsBuffer(buf));
    /* Bindings are per context; objects (and their state) are shared. */
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &v);
    CHECK(v == 0);
    glBindTexture(GL_TEXTURE_2D, tex);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, &v);
    CHECK(v == GL_CLAMP_TO_EDGE);
    glBindBuffer(GL_ARRAY_BUFFER, buf);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
    CHECK(v == (GLint)sizeof verts);
    /* A draw from the shared buffer. */
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor4f(0, 1, 0, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, (const void *)0);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    CHECK_PIXEL(4, 4, 0, 255, 0, 255, 0);
    /* Objects made here show up in the first context. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    CHECK_GL(GL_NO_ERROR);

    CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, alone));
    CHECK(!glIsTexture(tex) && !glIsBuffer(buf));
    glBindTexture(GL_TEXTURE_2D, tex); /* a new, unrelated texture of the same name */
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, &v);
    CHECK(v == GL_REPEAT);
    CHECK_GL(GL_NO_ERROR);

    CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, ct.context));
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, &v);
    CHECK(v == GL_CLAMP_TO_EDGE);
    glDeleteTextures(1, &tex);
    glDeleteBuffers(1, &buf);
    CHECK_GL(GL_NO_ERROR);
    CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, shared));
    CHECK(!glIsTexture(tex) && !glIsBuffer(buf));
    CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, alone));
    CHECK(glIsTexture(tex));

    CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, ct.context));
    eglDestroyContext(ct.display, shared);
    eglDestroyContext(ct.display, alone);
    return ct_done();
}
