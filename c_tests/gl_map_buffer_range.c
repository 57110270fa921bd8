/*
 * GL_EXT_map_buffer_range: glMapBufferRangeEXT returns the start of the range, reads see
 * the store, writes land in it (checked by mapping again and by drawing from the buffer),
 * glGetBufferPointervOES reports the range's start, glFlushMappedBufferRangeEXT validates
 * against the mapping; every error of both functions.
 */
#include "common.h"

static PFNGLMAPBUFFERRANGEEXTPROC glMapBufferRangeEXT;
static PFNGLFLUSHMAPPEDBUFFERRANGEEXTPROC glFlushMappedBufferRangeEXT;
static PFNGLUNMAPBUFFEROESPROC glUnmapBufferOES;
static PFNGLMAPBUFFEROESPROC glMapBufferOES;
static PFNGLGETBUFFERPOINTERVOESPROC glGetBufferPointervOES;

static void *map(GLintptr offset, GLsizeiptr length, GLbitfield access)
{
    return glMapBufferRangeEXT(GL_ARRAY_BUFFER, offset, length, access);
}

int main(void)
{
    GLubyte bytes[16];
    GLubyte *p;
    void *reported = NULL;
    GLuint buf[2];
    int i, same;

    ct_init(8, 8);
    glMapBufferRangeEXT = (PFNGLMAPBUFFERRANGEEXTPROC)eglGetProcAddress("glMapBufferRangeEXT");
    glFlushMappedBufferRangeEXT =
        (PFNGLFLUSHMAPPEDBUFFERRANGEEXTPROC)eglGetProcAddress("glFlushMappedBufferRangeEXT");
    glUnmapBufferOES = (PFNGLUNMAPBUFFEROESPROC)eglGetProcAddress("glUnmapBufferOES");
    glMapBufferOES = (PFNGLMAPBUFFEROESPROC)eglGetProcAddress("glMapBufferOES");
    glGetBufferPointervOES =
        (PFNGLGETBUFFERPOINTERVOESPROC)eglGetProcAddress("glGetBufferPointervOES");
    CHECK(strstr((const char *)glGetString(GL_EXTENSIONS), "GL_EXT_map_buffer_range") != NULL);
    CHECK(glMapBufferRangeEXT && glFlushMappedBufferRangeEXT && glUnmapBufferOES &&
          glMapBufferOES && glGetBufferPointervOES);
    if (!(glMapBufferRangeEXT && glFlushMappedBufferRangeEXT && glUnmapBufferOES &&
          glMapBufferOES && glGetBufferPointervOES))
        return ct_done();

    for (i = 0; i < 16; ++i)
        bytes[i] = (GLubyte)(i * 10);
    glGenBuffers(2, buf);
    glBindBuffer(GL_ARRAY_BUFFER, buf[0]);
    glBufferData(GL_ARRAY_BUFFER, 16, bytes, GL_DYNAMIC_DRAW);

    /* Read and write through a range; the reported pointer is the range's start. */
    p = (GLubyte *)map(4, 8, GL_MAP_READ_BIT_EXT | GL_MAP_WRITE_BIT_EXT);
    CHECK_GL(GL_NO_ERROR);
    CHECK(p != NULL);
    if (p == NULL)
        return ct_done();
    CHECK(p[0] == 40 && p[7] == 110);
    for (i = 0; i < 8; ++i)
        p[i] = (GLubyte)(200 + i);
    glGetBufferPointervOES(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER_OES, &reported);
    CHECK(reported == (void *)p);
    /* Mapped already: another map of either kind fails. */
    CHECK(map(0, 4, GL_MAP_READ_BIT_EXT) == NULL);
    CHECK_GL(GL_INVALID_OPERATION);
    CHECK(glMapBufferOES(GL_ARRAY_BUFFER, GL_WRITE_ONLY_OES) == NULL);
    CHECK_GL(GL_INVALID_OPERATION);
    /* Not mapped with FLUSH_EXPLICIT: nothing to flush. */
    glFlushMappedBufferRangeEXT(GL_ARRAY_BUFFER, 0, 4);
    CHECK_GL(GL_INVALID_OPERATION);
    CHECK(glUnmapBufferOES(GL_ARRAY_BUFFER) == GL_TRUE);
    p = (GLubyte *)map(0, 16, GL_MAP_READ_BIT_EXT);
    CHECK(p != NULL);
    if (p != NULL) {
        same = 1;
        for (i = 0; i < 16; ++i)
            same &= p[i] == (i >= 4 && i < 12 ? 200 + i - 4 : i * 10);
        CHECK(same);
    }
    CHECK(glUnmapBufferOES(GL_ARRAY_BUFFER) == GL_TRUE);
    CHECK_GL(GL_NO_ERROR);

    /* Explicit flushes: within the mapping (offsets relative to it), else INVALID_VALUE. */
    p = (GLubyte *)map(2, 8, GL_MAP_WRITE_BIT_EXT | GL_MAP_FLUSH_EXPLICIT_BIT_EXT |
                                 GL_MAP_INVALIDATE_RANGE_BIT_EXT);
    CHECK(p != NULL);
    glFlushMappedBufferRangeEXT(GL_ARRAY_BUFFER, 0, 8);
    CHECK_GL(GL_NO_ERROR);
    glFlushMappedBufferRangeEXT(GL_ARRAY_BUFFER, 4, 8);
    CHECK_GL(GL_INVALID_VALUE);
    glFlushMappedBufferRangeEXT(GL_ARRAY_BUFFER, -1, 2);
    CHECK_GL(GL_INVALID_VALUE);
    glFlushMappedBufferRangeEXT(GL_ARRAY_BUFFER, 0, -2);
    CHECK_GL(GL_INVALID_VALUE);
    glFlushMappedBufferRangeEXT(GL_TEXTURE_2D, 0, 2);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(glUnmapBufferOES(GL_ARRAY_BUFFER) == GL_TRUE);
    glFlushMappedBufferRangeEXT(GL_ARRAY_BUFFER, 0, 2);
    CHECK_GL(GL_INVALID_OPERATION);

    /* glMapBufferRangeEXT's errors. */
    CHECK(map(-1, 4, GL_MAP_READ_BIT_EXT) == NULL);
    CHECK_GL(GL_INVALID_VALUE);
    CHECK(map(0, -4, GL_MAP_READ_BIT_EXT) == NULL);
    CHECK_GL(GL_INVALID_VALUE);
    CHECK(map(8, 9, GL_MAP_READ_BIT_EXT) == NULL);
    CHECK_GL(GL_INVALID_VALUE);
    /* A bit no access flag has (0x40 and 0x80 would be desktop GL's persistent and coherent
     * bits, which Mesa judges by their own rules). */
    CHECK(map(0, 4, GL_MAP_READ_BIT_EXT | 0x1000) == NULL);
    CHECK_GL(GL_INVALID_VALUE);
    if (ct_strict()) {
        CHECK(map(0, 4, GL_MAP_READ_BIT_EXT | 0x40) == NULL);
        CHECK_GL(GL_INVALID_VALUE);
    }
    CHECK(map(0, 4, 0) == NULL);
    CHECK_GL(GL_INVALID_OPERATION);
    CHECK(map(0, 0, GL_MAP_READ_BIT_EXT) == NULL);
    CHECK_GL(GL_INVALID_OPERATION);
    CHECK(map(0, 4, GL_MAP_READ_BIT_EXT | GL_MAP_INVALIDATE_RANGE_BIT_EXT) == NULL);
    CHECK_GL(GL_INVALID_OPERATION);
    CHECK(map(0, 4, GL_MAP_READ_BIT_EXT | GL_MAP_INVALIDATE_BUFFER_BIT_EXT) == NULL);
    CHECK_GL(GL_INVALID_OPERATION);
    CHECK(map(0, 4, GL_MAP_READ_BIT_EXT | GL_MAP_UNSYNCHRONIZED_BIT_EXT) == NULL);
    CHECK_GL(GL_INVALID_OPERATION);
    CHECK(map(0, 4, GL_MAP_READ_BIT_EXT | GL_MAP_FLUSH_EXPLICIT_BIT_EXT) == NULL);
    CHECK_GL(GL_INVALID_OPERATION);
    CHECK(glMapBufferRangeEXT(GL_TEXTURE_2D, 0, 4, GL_MAP_READ_BIT_EXT) == NULL);
    CHECK_GL(GL_INVALID_ENUM);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    CHECK(map(0, 4, GL_MAP_READ_BIT_EXT) == NULL);
    CHECK_GL(GL_INVALID_OPERATION);
    glFlushMappedBufferRangeEXT(GL_ARRAY_BUFFER, 0, 2);
    CHECK_GL(GL_INVALID_OPERATION);

    /* A quad written through a mapped range of an element-free vertex buffer draws. */
    {
        static const GLfloat quad[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
        glBindBuffer(GL_ARRAY_BUFFER, buf[1]);
        glBufferData(GL_ARRAY_BUFFER, sizeof quad + 16, NULL, GL_STATIC_DRAW);
        p = (GLubyte *)map(16, sizeof quad, GL_MAP_WRITE_BIT_EXT | GL_MAP_INVALIDATE_RANGE_BIT_EXT);
        CHECK(p != NULL);
        if (p != NULL)
            memcpy(p, quad, sizeof quad);
        CHECK(glUnmapBufferOES(GL_ARRAY_BUFFER) == GL_TRUE);
        glEnableClientState(GL_VERTEX_ARRAY);
        glVertexPointer(2, GL_FLOAT, 0, (const void *)16);
        glColor4f(0, 1, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        CHECK_PIXEL(4, 4, 0, 255, 0, 255, 0);
        ct_save("mapped_quad");
    }
    glDeleteBuffers(2, buf);
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
