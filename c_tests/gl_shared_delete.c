/*
 * gl_shared_delete.c: an object deleted by one context of a share group while another
 * context has it bound loses its name at once, but the other context keeps using it (a
 * mapped buffer stays writable and drawable, a bound texture and renderbuffer stay
 * updatable) until it lets go. Under valgrind (GLES_CM_VALGRIND=1) a write through the
 * mapped pointer after the deletion would be an invalid write if the storage were freed.
 * ct:no-diff (Mesa frees the name the same way; the valgrind run is what this program is for)
 */
#define GL_GLEXT_PROTOTYPES 1
#include "common.h"

#include <stdint.h>

static const GLfloat quad[] = {-1, -1, 1, -1, -1, 1, 1, 1};

int main(void)
{
    static const GLubyte red[4 * 4 * 4] = {255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255};
    GLubyte green[4 * 4 * 4];
    EGLContext other;
    GLuint buf = 0, tex = 0, rb = 0, reused = 0;
    GLfloat *mapped, *again = NULL;
    GLint v = 0;
    int i;

    for (i = 0; i < 16; ++i) {
        green[4 * i] = 0;
        green[4 * i + 1] = 255;
        green[4 * i + 2] = 0;
        green[4 * i + 3] = 255;
    }
    ct_init(8, 8);
    other = eglCreateContext(ct.display, ct.config, ct.context, NULL);
    CHECK(other != EGL_NO_CONTEXT);

    /* Here: a mapped buffer, a bound texture, a bound renderbuffer. */
    glGenBuffers(1, &buf);
    glBindBuffer(GL_ARRAY_BUFFER, buf);
    glBufferData(GL_ARRAY_BUFFER, 4096, NULL, GL_DYNAMIC_DRAW);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, (const void *)0);
    mapped = (GLfloat *)glMapBufferOES(GL_ARRAY_BUFFER, GL_WRITE_ONLY_OES);
    CHECK(mapped != NULL);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, red);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glGenRenderbuffersOES(1, &rb);
    glBindRenderbufferOES(GL_RENDERBUFFER_OES, rb);
    CHECK_GL(GL_NO_ERROR);

    /* The other context deletes all three. */
    CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, other));
    glDeleteBuffers(1, &buf);
    glDeleteTextures(1, &tex);
    glDeleteRenderbuffersOES(1, &rb);
    CHECK_GL(GL_NO_ERROR);
    CHECK(!glIsBuffer(buf) && !glIsTexture(tex) && !glIsRenderbufferOES(rb));
    /* Its names are free again: a new object under a reused name is another object. */
    glGenBuffers(1, &reused);
    glBindBuffer(GL_ARRAY_BUFFER, reused);
    glBufferData(GL_ARRAY_BUFFER, 16, NULL, GL_STATIC_DRAW);
    CHECK_GL(GL_NO_ERROR);

    /* Back here, all three still work. */
    CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, ct.context));
    memcpy(mapped, quad, sizeof quad);
    memset(mapped + 8, 0x7f, 4096 - sizeof quad); /* the whole store stays writable */
    glGetBufferPointervOES(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER_OES, (void **)&again);
    CHECK(again == mapped);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &v);
    CHECK(v == (GLint)buf); /* the binding still reports the name it was made with */
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
    CHECK(v == 4096);
    CHECK(glUnmapBufferOES(GL_ARRAY_BUFFER) == GL_TRUE);
    CHECK_GL(GL_NO_ERROR);

    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, green);
    CHECK_GL(GL_NO_ERROR);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &v);
    CHECK(v == (GLint)tex);
    glEnable(GL_TEXTURE_2D);
    glBindBuffer(GL_ARRAY_BUFFER, 0); /* texture coordinates from client memory */
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, quad);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4); /* positions from the deleted buffer */
    CHECK_PIXEL(4, 4, 0, 255, 0, 255, 0);
    CHECK_GL(GL_NO_ERROR);

    glRenderbufferStorageOES(GL_RENDERBUFFER_OES, GL_RGB565_OES, 3, 5);
    glGetRenderbufferParameterivOES(GL_RENDERBUFFER_OES, GL_RENDERBUFFER_HEIGHT_OES, &v);
    CHECK(v == 5);
    CHECK_GL(GL_NO_ERROR);

    /* Letting go frees them (valgrind reports a definite leak otherwise at exit). */
    glDisableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, quad);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindRenderbufferOES(GL_RENDERBUFFER_OES, 0);
    CHECK_GL(GL_NO_ERROR);

    /* The other context's new buffer was never touched. */
    CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, other));
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
    CHECK(v == 16);
    CHECK(eglMakeCurrent(ct.display, ct.surface, ct.surface, ct.context));
    CHECK(eglDestroyContext(ct.display, other));
    return ct_done();
}
