/* Buffer objects and OES_mapbuffer: names, data, errors, queries, and drawing from VBOs. */
#include "common.h"

static GLint get_int(GLenum pname)
{
    GLint v = -1;
    glGetIntegerv(pname, &v);
    return v;
}

static const GLfloat verts[] = {-1, -1, 0, -1, -1, 0, 1, 1, 0, 1, 1, 0};
static const GLubyte colors[] = {255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255,
                                 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255};
static const GLushort indices[] = {0, 1, 2, 3, 4, 5};

/* Extension functions through eglGetProcAddress, as portable programs reach them. */
static PFNGLMAPBUFFEROESPROC map_buffer;
static PFNGLUNMAPBUFFEROESPROC unmap_buffer;
static PFNGLGETBUFFERPOINTERVOESPROC get_buffer_pointer;

static void check_picture(int line)
{
    GLubyte p[4];
    ct_read(2, 2, p);
    CHECK(p[0] == 255 && p[1] == 0 && p[2] == 0 && p[3] == 255);
    ct_read(13, 13, p);
    CHECK(p[0] == 0 && p[1] == 0 && p[2] == 255 && p[3] == 255);
    if (ct.failures)
        fprintf(stderr, "(picture from line %d)\n", line);
}

int main(void)
{
    GLuint buf[3] = {0, 0, 0};
    GLint v = 0;
    void *ptr = (void *)1;
    GLubyte *map;
    GLubyte bytes[8] = {1, 2, 3, 4, 5, 6, 7, 8};

    ct_init(16, 16);
    map_buffer = (PFNGLMAPBUFFEROESPROC)eglGetProcAddress("glMapBufferOES");
    unmap_buffer = (PFNGLUNMAPBUFFEROESPROC)eglGetProcAddress("glUnmapBufferOES");
    get_buffer_pointer =
        (PFNGLGETBUFFERPOINTERVOESPROC)eglGetProcAddress("glGetBufferPointervOES");
    CHECK(map_buffer && unmap_buffer && get_buffer_pointer);
    if (!map_buffer || !unmap_buffer || !get_buffer_pointer)
        return ct_done();
    glShadeModel(GL_FLAT);

    CHECK(get_int(GL_ARRAY_BUFFER_BINDING) == 0);
    CHECK(get_int(GL_ELEMENT_ARRAY_BUFFER_BINDING) == 0);
    glGenBuffers(-1, buf);
    CHECK_GL(GL_INVALID_VALUE);
    glGenBuffers(3, buf);
    CHECK(buf[0] && buf[1] && buf[2] && buf[0] != buf[1] && buf[1] != buf[2]);
    CHECK(!glIsBuffer(buf[0]) && !glIsBuffer(0));
    glBindBuffer(GL_ARRAY_BUFFER + 7, buf[0]);
    CHECK_GL(GL_INVALID_ENUM);
    glBindBuffer(GL_ARRAY_BUFFER, buf[0]);
    CHECK(glIsBuffer(buf[0]));
    CHECK(get_int(GL_ARRAY_BUFFER_BINDING) == (GLint)buf[0]);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
    CHECK(v == 0);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_USAGE, &v);
    CHECK(v == GL_STATIC_DRAW);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS_OES, &v);
    CHECK(v == GL_WRITE_ONLY_OES);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED_OES, &v);
    CHECK(v == GL_FALSE);
    CHECK_GL(GL_NO_ERROR);

    /* BufferData / BufferSubData errors. */
    glBufferData(GL_ARRAY_BUFFER + 7, 8, bytes, GL_STATIC_DRAW);
    CHECK_GL(GL_INVALID_ENUM);
    glBufferData(GL_ARRAY_BUFFER, 8, bytes, GL_STATIC_DRAW + 0x10); /* a made-up usage */
    CHECK_GL(GL_INVALID_ENUM);
    glBufferData(GL_ARRAY_BUFFER, -1, bytes, GL_STATIC_DRAW);
    CHECK_GL(GL_INVALID_VALUE);
    glBufferData(GL_ARRAY_BUFFER, 8, bytes, GL_DYNAMIC_DRAW);
    CHECK_GL(GL_NO_ERROR);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
    CHECK(v == 8);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_USAGE, &v);
    CHECK(v == GL_DYNAMIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 4, 4, bytes);
    CHECK_GL(GL_NO_ERROR);
    glBufferSubData(GL_ARRAY_BUFFER, 6, 4, bytes);
    CHECK_GL(GL_INVALID_VALUE);
    glBufferSubData(GL_ARRAY_BUFFER, -1, 1, bytes);
    CHECK_GL(GL_INVALID_VALUE);
    glBufferSubData(GL_ARRAY_BUFFER, 0, -1, bytes);
    CHECK_GL(GL_INVALID_VALUE);
    glBufferSubData(GL_ARRAY_BUFFER + 7, 0, 1, bytes);
    CHECK_GL(GL_INVALID_ENUM);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE + 100, &v);
    CHECK_GL(GL_INVALID_ENUM);
    glGetBufferParameteriv(GL_ARRAY_BUFFER + 7, GL_BUFFER_SIZE, &v);
    CHECK_GL(GL_INVALID_ENUM);

    /* Mapping. */
    map = (GLubyte *)map_buffer(GL_ARRAY_BUFFER, 0x88B8 /* GL_READ_ONLY: not in ES 1.1 */);
    CHECK(map == NULL);
    CHECK_GL(GL_INVALID_ENUM);
    get_buffer_pointer(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER_OES, &ptr);
    CHECK(ptr == NULL);
    map = (GLubyte *)map_buffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY_OES);
    CHECK(map != NULL);
    CHECK_GL(GL_NO_ERROR);
    if (map)
        map[0] = 42;
    get_buffer_pointer(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER_OES, &ptr);
    CHECK(ptr == (void *)map);
    get_buffer_pointer(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &ptr);
    CHECK_GL(GL_INVALID_ENUM);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED_OES, &v);
    CHECK(v == GL_TRUE);
    CHECK(map_buffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY_OES) == NULL);
    CHECK_GL(GL_INVALID_OPERATION);
    glBufferSubData(GL_ARRAY_BUFFER, 0, 1, bytes);
    CHECK_GL(GL_INVALID_OPERATION);
    CHECK(unmap_buffer(GL_ARRAY_BUFFER) == GL_TRUE);
    CHECK(unmap_buffer(GL_ARRAY_BUFFER) == GL_FALSE);
    CHECK_GL(GL_INVALID_OPERATION);

    /* No buffer bound: INVALID_OPERATION. */
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBufferData(GL_ARRAY_BUFFER, 8, bytes, GL_STATIC_DRAW);
    CHECK_GL(GL_INVALID_OPERATION);
    glBufferSubData(GL_ARRAY_BUFFER, 0, 1, bytes);
    CHECK_GL(GL_INVALID_OPERATION);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
    CHECK_GL(GL_INVALID_OPERATION);
    CHECK(map_buffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY_OES) == NULL);
    CHECK_GL(GL_INVALID_OPERATION);
    CHECK(unmap_buffer(GL_ARRAY_BUFFER) == GL_FALSE);
    CHECK_GL(GL_INVALID_OPERATION);

    /* The reference picture from client arrays: red bottom-left, blue top-right triangle. */
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glVertexPointer(2, GL_FLOAT, 0, verts);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, indices);
    check_picture(__LINE__);

    /* The same from buffer objects: vertices and colors share one buffer (offsets), the
     * indices are in an element buffer. */
    glBindBuffer(GL_ARRAY_BUFFER, buf[1]);
    glBufferData(GL_ARRAY_BUFFER, sizeof verts + sizeof colors, NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof verts, verts);
    glBufferSubData(GL_ARRAY_BUFFER, sizeof verts, sizeof colors, colors);
    glVertexPointer(2, GL_FLOAT, 0, (const void *)0);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, (const void *)sizeof verts);
    glBindBuffer(GL_ARRAY_BUFFER, 0); /* the pointers keep their buffer */
    CHECK(get_int(GL_VERTEX_ARRAY_BUFFER_BINDING) == (GLint)buf[1]);
    CHECK(get_int(GL_COLOR_ARRAY_BUFFER_BINDING) == (GLint)buf[1]);
    CHECK(get_int(GL_NORMAL_ARRAY_BUFFER_BINDING) == 0);
    CHECK(get_int(GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING) == 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buf[2]);
    CHECK(get_int(GL_ELEMENT_ARRAY_BUFFER_BINDING) == (GLint)buf[2]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof indices + 2, NULL, GL_STATIC_DRAW);
    map = (GLubyte *)map_buffer(GL_ELEMENT_ARRAY_BUFFER, GL_WRITE_ONLY_OES);
    CHECK(map != NULL);
    if (map)
        memcpy(map + 2, indices, sizeof indices);
    CHECK(unmap_buffer(GL_ELEMENT_ARRAY_BUFFER) == GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, (const void *)2);
    CHECK_GL(GL_NO_ERROR);
    check_picture(__LINE__);
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    check_picture(__LINE__);
    CHECK_GL(GL_NO_ERROR);

    /* Deleting unbinds from the targets and the array pointers. */
    glDeleteBuffers(-1, buf);
    CHECK_GL(GL_INVALID_VALUE);
    glDeleteBuffers(2, &buf[1]);
    CHECK_GL(GL_NO_ERROR);
    CHECK(!glIsBuffer(buf[1]) && !glIsBuffer(buf[2]));
    CHECK(get_int(GL_VERTEX_ARRAY_BUFFER_BINDING) == 0);
    CHECK(get_int(GL_COLOR_ARRAY_BUFFER_BINDING) == 0);
    CHECK(get_int(GL_ELEMENT_ARRAY_BUFFER_BINDING) == 0);
    glDeleteBuffers(1, &buf[0]);
    CHECK_GL(GL_NO_ERROR);

    return ct_done();
}
