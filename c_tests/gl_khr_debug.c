/*
 * gl_khr_debug.c: GL_KHR_debug. Debug output starts disabled (ct_init's context is not a
 * debug context); enabled, every GL error becomes a message naming the call, the argument and
 * its value; the log keeps 64 messages and is read back with exact counts and lengths;
 * message control filters by source, type, severity and ids; debug groups push and pop
 * their messages and control state; object labels for each ES 1.1 namespace; the callback
 * and its user parameter through glGetPointervKHR; every error the extension lists.
 * ct:no-diff (the messages' text is this library's own)
 */
#include "common.h"

/* Extension functions through eglGetProcAddress. */
static PFNGLDEBUGMESSAGECONTROLKHRPROC glDebugMessageControlKHR;
static PFNGLDEBUGMESSAGEINSERTKHRPROC glDebugMessageInsertKHR;
static PFNGLDEBUGMESSAGECALLBACKKHRPROC glDebugMessageCallbackKHR;
static PFNGLGETDEBUGMESSAGELOGKHRPROC glGetDebugMessageLogKHR;
static PFNGLPUSHDEBUGGROUPKHRPROC glPushDebugGroupKHR;
static PFNGLPOPDEBUGGROUPKHRPROC glPopDebugGroupKHR;
static PFNGLOBJECTLABELKHRPROC glObjectLabelKHR;
static PFNGLGETOBJECTLABELKHRPROC glGetObjectLabelKHR;
static PFNGLOBJECTPTRLABELKHRPROC glObjectPtrLabelKHR;
static PFNGLGETOBJECTPTRLABELKHRPROC glGetObjectPtrLabelKHR;
static PFNGLGETPOINTERVKHRPROC glGetPointervKHR;
static PFNGLGENRENDERBUFFERSOESPROC glGenRenderbuffersOES;
static PFNGLBINDRENDERBUFFEROESPROC glBindRenderbufferOES;
static PFNGLGENFRAMEBUFFERSOESPROC glGenFramebuffersOES;
static PFNGLBINDFRAMEBUFFEROESPROC glBindFramebufferOES;
static PFNGLGENVERTEXARRAYSOESPROC glGenVertexArraysOES;
static PFNGLBINDVERTEXARRAYOESPROC glBindVertexArrayOES;
static PFNGLDELETEVERTEXARRAYSOESPROC glDeleteVertexArraysOES;

#define APP GL_DEBUG_SOURCE_APPLICATION_KHR
#define OTHER GL_DEBUG_TYPE_OTHER_KHR
#define NOTE GL_DEBUG_SEVERITY_NOTIFICATION_KHR

static GLint integer(GLenum pname)
{
    GLint v = -1;
    glGetIntegerv(pname, &v);
    return v;
}

/* One message read from the log (at most 1024 bytes with its terminator). */
static struct {
    GLenum source, type, severity;
    GLuint id;
    GLsizei length;
    char text[1024];
} got;

/* Fetches the oldest logged message into `got`; returns how many were fetched (0 or 1). */
static GLuint fetch(void)
{
    memset(&got, 0, sizeof got);
    return glGetDebugMessageLogKHR(1, (GLsizei)sizeof got.text, &got.source, &got.type, &got.id,
                                   &got.severity, &got.length, got.text);
}

/* Empties the log. */
static void drain(void)
{
    while (integer(GL_DEBUG_LOGGED_MESSAGES_KHR) > 0)
        glGetDebugMessageLogKHR(64, 0, NULL, NULL, NULL, NULL, NULL, NULL);
}

static void insert(GLuint id, GLenum severity, const char *text)
{
    glDebugMessageInsertKHR(APP, OTHER, id, severity, -1, text);
}

/* What the callback saw. */
static struct {
    int calls;
    GLenum source, type, severity;
    GLuint id;
    GLsizei length;
    char text[1024];
    const void *user;
} cb;

static void GL_APIENTRY callback(GLenum source, GLenum type, GLuint id, GLenum severity,
                                 GLsizei length, const GLchar *message, const void *user)
{
    ++cb.calls;
    cb.source = source;
    cb.type = type;
    cb.id = id;
    cb.severity = severity;
    cb.length = length;
    cb.user = user;
    strncpy(cb.text, message, sizeof cb.text - 1);
}

static void check_errors_in_words(void)
{
    static const char enable_msg[] =
        "glEnable: GL_INVALID_ENUM (0x0500): cap is 0x1234 (not a token of this "
        "implementation), which is not a value this call accepts for cap";

    /* Disabled by default: errors are raised, no message is logged. */
    CHECK(!glIsEnabled(GL_DEBUG_OUTPUT_KHR));
    glEnable(0x1234);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 0);

    glEnable(GL_DEBUG_OUTPUT_KHR);
    CHECK(glIsEnabled(GL_DEBUG_OUTPUT_KHR));
    CHECK(!glIsEnabled(GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR));
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR);
    CHECK(glIsEnabled(GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR));
    CHECK(integer(GL_MAX_DEBUG_MESSAGE_LENGTH_KHR) == 1024);
    CHECK(integer(GL_MAX_DEBUG_LOGGED_MESSAGES_KHR) == 64);
    CHECK(integer(GL_MAX_DEBUG_GROUP_STACK_DEPTH_KHR) == 64);
    CHECK(integer(GL_MAX_LABEL_LENGTH_KHR) == 256);
    CHECK(integer(GL_DEBUG_GROUP_STACK_DEPTH_KHR) == 1);
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 0);
    CHECK(integer(GL_DEBUG_NEXT_LOGGED_MESSAGE_LENGTH_KHR) == 0);
    CHECK_GL(GL_NO_ERROR);

    glEnable(0x1234);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 1);
    CHECK(integer(GL_DEBUG_NEXT_LOGGED_MESSAGE_LENGTH_KHR) == (GLint)sizeof enable_msg);
    CHECK(fetch() == 1);
    CHECK(got.source == GL_DEBUG_SOURCE_API_KHR);
    CHECK(got.type == GL_DEBUG_TYPE_ERROR_KHR);
    CHECK(got.id == GL_INVALID_ENUM);
    CHECK(got.severity == GL_DEBUG_SEVERITY_HIGH_KHR);
    CHECK(got.length == (GLsizei)sizeof enable_msg);
    CHECK(strcmp(got.text, enable_msg) == 0);
    if (strcmp(got.text, enable_msg) != 0)
        fprintf(stderr, "message: %s\n", got.text);
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 0);

    /* The enum's name when it is a token, the call's name for every error. */
    CHECK(glGetString(GL_TEXTURE_2D) == NULL);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(fetch() == 1);
    CHECK(strstr(got.text, "glGetString") == got.text);
    CHECK(strstr(got.text, "name is 0x0DE1 (GL_TEXTURE_2D)") != NULL);
    glGetIntegerv(0x9999, NULL);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(fetch() == 1);
    CHECK(strstr(got.text, "glGetIntegerv: GL_INVALID_ENUM (0x0500): pname is 0x9999") == got.text);
    glTexParameteri(GL_TEXTURE_2D, 0x1234, 0);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(fetch() == 1);
    CHECK(strstr(got.text, "glTexParameteri: GL_INVALID_ENUM (0x0500): ") == got.text);
    glDeleteTextures(-1, NULL);
    CHECK_GL(GL_INVALID_VALUE);
    CHECK(fetch() == 1);
    CHECK(got.id == GL_INVALID_VALUE);
    CHECK(strstr(got.text, "glDeleteTextures: GL_INVALID_VALUE (0x0501): n is -1") == got.text);
    glPopMatrix();
    CHECK_GL(GL_STACK_UNDERFLOW);
    CHECK(fetch() == 1);
    CHECK(got.id == GL_STACK_UNDERFLOW);
    CHECK(strstr(got.text, "glPopMatrix: GL_STACK_UNDERFLOW (0x0504)") == got.text);
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 0);
}

static void check_log(void)
{
    GLenum sources[4], types[4], severities[4];
    GLuint ids[4];
    GLsizei lengths[4];
    char buf[64];
    int i;

    insert(1, NOTE, "one");
    insert(2, GL_DEBUG_SEVERITY_MEDIUM_KHR, "second");
    glDebugMessageInsertKHR(GL_DEBUG_SOURCE_THIRD_PARTY_KHR, GL_DEBUG_TYPE_MARKER_KHR, 3,
                            GL_DEBUG_SEVERITY_HIGH_KHR, 5, "threefold"); /* "three" */
    CHECK_GL(GL_NO_ERROR);
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 3);
    CHECK(integer(GL_DEBUG_NEXT_LOGGED_MESSAGE_LENGTH_KHR) == 4);

    /* count 0 fetches nothing; "one\0" fits in 4 bytes, "second\0" in 7 more. */
    CHECK(glGetDebugMessageLogKHR(0, sizeof buf, sources, types, ids, severities, lengths, buf) ==
          0);
    CHECK(glGetDebugMessageLogKHR(4, 10, sources, types, ids, severities, lengths, buf) == 1);
    CHECK(ids[0] == 1 && lengths[0] == 4 && severities[0] == NOTE && strcmp(buf, "one") == 0);
    CHECK(sources[0] == APP && types[0] == OTHER);
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 2);
    CHECK(integer(GL_DEBUG_NEXT_LOGGED_MESSAGE_LENGTH_KHR) == 7);
    CHECK(glGetDebugMessageLogKHR(4, 6, sources, types, ids, severities, lengths, buf) == 0);
    CHECK(glGetDebugMessageLogKHR(4, sizeof buf, sources, types, ids, severities, lengths, buf) ==
          2);
    CHECK(ids[0] == 2 && lengths[0] == 7 && strcmp(buf, "second") == 0);
    CHECK(ids[1] == 3 && lengths[1] == 6 && strcmp(buf + 7, "three") == 0);
    CHECK(sources[1] == GL_DEBUG_SOURCE_THIRD_PARTY_KHR && types[1] == GL_DEBUG_TYPE_MARKER_KHR);
    CHECK(severities[1] == GL_DEBUG_SEVERITY_HIGH_KHR);
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 0);
    CHECK_GL(GL_NO_ERROR);

    /* A negative bufSize with a buffer is an error, and fetches nothing. */
    insert(4, NOTE, "four");
    CHECK(glGetDebugMessageLogKHR(1, -1, NULL, NULL, NULL, NULL, NULL, buf) == 0);
    CHECK_GL(GL_INVALID_VALUE);
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 2); /* "four" and the error's message */
    /* Without a buffer, bufSize is ignored. */
    CHECK(glGetDebugMessageLogKHR(1, -1, NULL, NULL, ids, NULL, lengths, NULL) == 1);
    CHECK(ids[0] == 4 && lengths[0] == 5);
    CHECK(fetch() == 1);
    CHECK(strstr(got.text, "glGetDebugMessageLogKHR: GL_INVALID_VALUE (0x0501): bufSize is -1") ==
          got.text);

    /* The log keeps 64 messages and drops later ones. */
    for (i = 0; i < 70; ++i)
        insert((GLuint)(100 + i), NOTE, "x");
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 64);
    CHECK(glGetDebugMessageLogKHR(4, sizeof buf, NULL, NULL, ids, NULL, NULL, buf) == 4);
    CHECK(ids[0] == 100 && ids[3] == 103);
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 60);
    drain();

    /* Disabled output logs nothing, inserted or raised. */
    glDisable(GL_DEBUG_OUTPUT_KHR);
    insert(5, NOTE, "lost");
    glEnable(0x1234);
    CHECK_GL(GL_INVALID_ENUM);
    glEnable(GL_DEBUG_OUTPUT_KHR);
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 0);
}

static void check_insert_errors(void)
{
    static char long_text[1025];

    glDebugMessageInsertKHR(GL_DEBUG_SOURCE_API_KHR, OTHER, 1, NOTE, -1, "api");
    CHECK_GL(GL_INVALID_ENUM);
    glDebugMessageInsertKHR(GL_DONT_CARE, OTHER, 1, NOTE, -1, "any");
    CHECK_GL(GL_INVALID_ENUM);
    glDebugMessageInsertKHR(APP, GL_DONT_CARE, 1, NOTE, -1, "any");
    CHECK_GL(GL_INVALID_ENUM);
    glDebugMessageInsertKHR(APP, 0x1234, 1, NOTE, -1, "bad");
    CHECK_GL(GL_INVALID_ENUM);
    glDebugMessageInsertKHR(APP, OTHER, 1, GL_DONT_CARE, -1, "any");
    CHECK_GL(GL_INVALID_ENUM);
    glDebugMessageInsertKHR(APP, OTHER, 1, 0x1234, -1, "bad");
    CHECK_GL(GL_INVALID_ENUM);
    /* 1023 characters are allowed, 1024 are not (terminated or counted). */
    memset(long_text, 'a', 1023);
    insert(1, NOTE, long_text);
    CHECK_GL(GL_NO_ERROR);
    long_text[1023] = 'a';
    insert(1, NOTE, long_text);
    CHECK_GL(GL_INVALID_VALUE);
    glDebugMessageInsertKHR(APP, OTHER, 1, NOTE, 1024, long_text);
    CHECK_GL(GL_INVALID_VALUE);
    /* Six errors, one message, two errors: nine messages, the first error named. */
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 9);
    CHECK(fetch() == 1);
    CHECK(strstr(got.text, "glDebugMessageInsertKHR: GL_INVALID_ENUM (0x0500): source is 0x8246 (GL_DEBUG_SOURCE_API_KHR)") ==
          got.text);
    CHECK(strstr(got.text, "GL_DEBUG_SOURCE_APPLICATION_KHR") != NULL);
    drain();
}

static void check_control(void)
{
    static const GLuint seven = 7;

    /* Low severity starts disabled; everything else enabled. */
    insert(1, GL_DEBUG_SEVERITY_LOW_KHR, "low");
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 0);
    glDebugMessageControlKHR(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_LOW_KHR, 0, NULL,
                             GL_TRUE);
    insert(1, GL_DEBUG_SEVERITY_LOW_KHR, "low");
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 1);
    drain();

    /* By id (for one source and type), by severity, by source. */
    glDebugMessageControlKHR(APP, OTHER, GL_DONT_CARE, 1, &seven, GL_FALSE);
    insert(7, NOTE, "seven");
    insert(8, NOTE, "eight");
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 1);
    CHECK(fetch() == 1 && got.id == 8);
    glDebugMessageControlKHR(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_MEDIUM_KHR, 0, NULL,
                             GL_FALSE);
    insert(9, GL_DEBUG_SEVERITY_MEDIUM_KHR, "nine");
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 0);
    glDebugMessageControlKHR(GL_DEBUG_SOURCE_API_KHR, GL_DONT_CARE, GL_DONT_CARE, 0, NULL,
                             GL_FALSE);
    glEnable(0x1234);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 0);
    /* Everything back on: the later call wins. */
    glDebugMessageControlKHR(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, NULL, GL_TRUE);
    insert(7, NOTE, "seven");
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 1);
    drain();

    /* Errors. */
    glDebugMessageControlKHR(0x1234, GL_DONT_CARE, GL_DONT_CARE, 0, NULL, GL_TRUE);
    CHECK_GL(GL_INVALID_ENUM);
    glDebugMessageControlKHR(GL_DONT_CARE, 0x1234, GL_DONT_CARE, 0, NULL, GL_TRUE);
    CHECK_GL(GL_INVALID_ENUM);
    glDebugMessageControlKHR(GL_DONT_CARE, GL_DONT_CARE, 0x1234, 0, NULL, GL_TRUE);
    CHECK_GL(GL_INVALID_ENUM);
    glDebugMessageControlKHR(APP, OTHER, GL_DONT_CARE, -1, NULL, GL_TRUE);
    CHECK_GL(GL_INVALID_VALUE);
    glDebugMessageControlKHR(GL_DONT_CARE, OTHER, GL_DONT_CARE, 1, &seven, GL_TRUE);
    CHECK_GL(GL_INVALID_OPERATION);
    glDebugMessageControlKHR(APP, GL_DONT_CARE, GL_DONT_CARE, 1, &seven, GL_TRUE);
    CHECK_GL(GL_INVALID_OPERATION);
    glDebugMessageControlKHR(APP, OTHER, NOTE, 1, &seven, GL_TRUE);
    CHECK_GL(GL_INVALID_OPERATION);
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 7);
    CHECK(fetch() == 1);
    CHECK(strstr(got.text, "glDebugMessageControlKHR: GL_INVALID_ENUM (0x0500): source is 0x1234") ==
          got.text);
    drain();
}

static void check_callback(void)
{
    static int user;
    void *p = NULL;

    glGetPointervKHR(GL_DEBUG_CALLBACK_FUNCTION_KHR, &p);
    CHECK(p == NULL);
    glDebugMessageCallbackKHR(callback, &user);
    glGetPointervKHR(GL_DEBUG_CALLBACK_USER_PARAM_KHR, &p);
    CHECK(p == (void *)&user);
    glGetPointervKHR(GL_DEBUG_CALLBACK_FUNCTION_KHR, &p);
    CHECK(p != NULL);
    glGetPointerv(GL_DEBUG_CALLBACK_USER_PARAM_KHR, &p); /* the core query knows them too */
    CHECK(p == (void *)&user);

    glBlendFunc(GL_ONE, 0x4321);
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(cb.calls == 1);
    CHECK(cb.source == GL_DEBUG_SOURCE_API_KHR && cb.type == GL_DEBUG_TYPE_ERROR_KHR);
    CHECK(cb.id == GL_INVALID_ENUM && cb.severity == GL_DEBUG_SEVERITY_HIGH_KHR);
    CHECK(cb.user == &user);
    CHECK(strstr(cb.text, "glBlendFunc: GL_INVALID_ENUM (0x0500)") == cb.text);
    CHECK(cb.length == (GLsizei)strlen(cb.text));
    /* With a callback, nothing goes to the log. */
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 0);
    insert(42, NOTE, "to the callback");
    CHECK(cb.calls == 2 && cb.id == 42 && strcmp(cb.text, "to the callback") == 0);
    CHECK(cb.source == APP && cb.type == OTHER && cb.severity == NOTE && cb.length == 15);

    glDebugMessageCallbackKHR(NULL, NULL);
    glGetPointervKHR(GL_DEBUG_CALLBACK_FUNCTION_KHR, &p);
    CHECK(p == NULL);
    insert(43, NOTE, "to the log");
    CHECK(cb.calls == 2);
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 1);
    drain();

    glGetPointervKHR(0x1234, &p);
    CHECK_GL(GL_INVALID_ENUM);
    glVertexPointer(2, GL_FLOAT, 0, &user);
    glGetPointervKHR(GL_VERTEX_ARRAY_POINTER, &p);
    CHECK(p == (void *)&user);
    CHECK_GL(GL_NO_ERROR);
    drain();
}

static void check_groups(void)
{
    char long_text[1025];
    int i;

    glPushDebugGroupKHR(APP, 11, -1, "frame");
    CHECK_GL(GL_NO_ERROR);
    CHECK(integer(GL_DEBUG_GROUP_STACK_DEPTH_KHR) == 2);
    CHECK(fetch() == 1);
    CHECK(got.source == APP && got.type == GL_DEBUG_TYPE_PUSH_GROUP_KHR && got.id == 11);
    CHECK(got.severity == NOTE && strcmp(got.text, "frame") == 0 && got.length == 6);
    /* Control inside the group ends with it. */
    glDebugMessageControlKHR(APP, GL_DONT_CARE, GL_DONT_CARE, 0, NULL, GL_FALSE);
    insert(1, NOTE, "hidden");
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 0);
    glPopDebugGroupKHR();
    CHECK(integer(GL_DEBUG_GROUP_STACK_DEPTH_KHR) == 1);
    CHECK(fetch() == 1);
    CHECK(got.source == APP && got.type == GL_DEBUG_TYPE_POP_GROUP_KHR && got.id == 11);
    CHECK(got.severity == NOTE && strcmp(got.text, "frame") == 0);
    insert(1, NOTE, "shown");
    CHECK(integer(GL_DEBUG_LOGGED_MESSAGES_KHR) == 1);
    drain();

    /* A counted message; a third-party group. */
    glPushDebugGroupKHR(GL_DEBUG_SOURCE_THIRD_PARTY_KHR, 12, 3, "abcdef");
    CHECK(fetch() == 1 && strcmp(got.text, "abc") == 0);
    CHECK(got.source == GL_DEBUG_SOURCE_THIRD_PARTY_KHR);
    glPopDebugGroupKHR();
    drain();

    /* Errors: source, length, overflow, underflow. */
    glPushDebugGroupKHR(GL_DEBUG_SOURCE_API_KHR, 1, -1, "api");
    CHECK_GL(GL_INVALID_ENUM);
    memset(long_text, 'b', 1024);
    long_text[1024] = 0;
    glPushDebugGroupKHR(APP, 1, -1, long_text);
    CHECK_GL(GL_INVALID_VALUE);
    glPushDebugGroupKHR(APP, 1, 1024, long_text);
    CHECK_GL(GL_INVALID_VALUE);
    CHECK(integer(GL_DEBUG_GROUP_STACK_DEPTH_KHR) == 1);
    drain();
    glDisable(GL_DEBUG_OUTPUT_KHR);
    for (i = 1; i < 64; ++i)
        glPushDebugGroupKHR(APP, (GLuint)i, -1, "level");
    CHECK_GL(GL_NO_ERROR);
    CHECK(integer(GL_DEBUG_GROUP_STACK_DEPTH_KHR) == 64);
    glEnable(GL_DEBUG_OUTPUT_KHR);
    glPushDebugGroupKHR(APP, 64, -1, "one too many");
    CHECK_GL(GL_STACK_OVERFLOW_KHR);
    CHECK(fetch() == 1 && got.id == GL_STACK_OVERFLOW_KHR);
    CHECK(strstr(got.text, "glPushDebugGroupKHR: GL_STACK_OVERFLOW (0x0503)") == got.text);
    glDisable(GL_DEBUG_OUTPUT_KHR);
    for (i = 1; i < 64; ++i)
        glPopDebugGroupKHR();
    CHECK_GL(GL_NO_ERROR);
    glEnable(GL_DEBUG_OUTPUT_KHR);
    glPopDebugGroupKHR();
    CHECK_GL(GL_STACK_UNDERFLOW_KHR);
    CHECK(fetch() == 1 && got.id == GL_STACK_UNDERFLOW_KHR);
    CHECK(strstr(got.text, "glPopDebugGroupKHR: GL_STACK_UNDERFLOW (0x0504)") == got.text);
    CHECK(integer(GL_DEBUG_GROUP_STACK_DEPTH_KHR) == 1);
}

/* Labels `name` of `identifier`, reads it back whole, cut short and by length only. */
static void check_label(GLenum identifier, GLuint name)
{
    char buf[300];
    GLsizei len = -1;

    glObjectLabelKHR(identifier, name, -1, "my object");
    CHECK_GL(GL_NO_ERROR);
    glGetObjectLabelKHR(identifier, name, sizeof buf, &len, buf);
    CHECK(len == 9 && strcmp(buf, "my object") == 0);
    glGetObjectLabelKHR(identifier, name, 3, &len, buf);
    CHECK(len == 2 && strcmp(buf, "my") == 0);
    glGetObjectLabelKHR(identifier, name, 0, &len, NULL);
    CHECK(len == 9);
    glObjectLabelKHR(identifier, name, 2, "my object");
    glGetObjectLabelKHR(identifier, name, sizeof buf, &len, buf);
    CHECK(len == 2 && strcmp(buf, "my") == 0);
    /* A NULL label removes it. */
    glObjectLabelKHR(identifier, name, 0, NULL);
    glGetObjectLabelKHR(identifier, name, sizeof buf, &len, buf);
    CHECK(len == 0 && buf[0] == 0);
    CHECK_GL(GL_NO_ERROR);
    /* 255 characters fit, 256 do not. */
    memset(buf, 'c', 256);
    buf[256] = 0;
    glObjectLabelKHR(identifier, name, 255, buf);
    CHECK_GL(GL_NO_ERROR);
    glObjectLabelKHR(identifier, name, -1, buf);
    CHECK_GL(GL_INVALID_VALUE);
    glObjectLabelKHR(identifier, name, 256, buf);
    CHECK_GL(GL_INVALID_VALUE);
    glGetObjectLabelKHR(identifier, name, sizeof buf, &len, buf);
    CHECK(len == 255);
    glGetObjectLabelKHR(identifier, name, -1, &len, buf);
    CHECK_GL(GL_INVALID_VALUE);
    /* Not an object of the namespace. */
    glObjectLabelKHR(identifier, 4321, -1, "none");
    CHECK_GL(GL_INVALID_VALUE);
    glGetObjectLabelKHR(identifier, 4321, sizeof buf, &len, buf);
    CHECK_GL(GL_INVALID_VALUE);
}

static void check_labels(void)
{
    static const GLenum not_es1[] = {GL_SHADER_KHR, GL_PROGRAM_KHR, GL_QUERY_KHR,
                                     GL_PROGRAM_PIPELINE_KHR, GL_SAMPLER_KHR, 0x1234};
    GLuint buffer, texture, renderbuffer, framebuffer, vao, unbound;
    char buf[32];
    GLsizei len = 0;
    unsigned i;

    glGenBuffers(1, &buffer);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glGenRenderbuffersOES(1, &renderbuffer);
    glBindRenderbufferOES(GL_RENDERBUFFER_OES, renderbuffer);
    glGenFramebuffersOES(1, &framebuffer);
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, framebuffer);
    glBindFramebufferOES(GL_FRAMEBUFFER_OES, 0);
    glGenVertexArraysOES(1, &vao);
    glBindVertexArrayOES(vao);
    glBindVertexArrayOES(0);
    CHECK_GL(GL_NO_ERROR);

    check_label(GL_BUFFER_KHR, buffer);
    check_label(GL_TEXTURE, texture);
    check_label(GL_RENDERBUFFER_OES, renderbuffer);
    check_label(GL_FRAMEBUFFER_OES, framebuffer);
    check_label(GL_VERTEX_ARRAY_KHR, vao);

    /* Namespaces ES 1.1 does not have. */
    for (i = 0; i < sizeof not_es1 / sizeof not_es1[0]; ++i) {
        glObjectLabelKHR(not_es1[i], 1, -1, "x");
        CHECK_GL(GL_INVALID_ENUM);
        glGetObjectLabelKHR(not_es1[i], 1, sizeof buf, &len, buf);
        CHECK_GL(GL_INVALID_ENUM);
    }
    /* A name generated but never bound is no object yet. */
    glGenTextures(1, &unbound);
    glObjectLabelKHR(GL_TEXTURE, unbound, -1, "x");
    CHECK_GL(GL_INVALID_VALUE);
    /* Deleting an object deletes its label. */
    glObjectLabelKHR(GL_VERTEX_ARRAY_KHR, vao, -1, "gone");
    glDeleteVertexArraysOES(1, &vao);
    glGetObjectLabelKHR(GL_VERTEX_ARRAY_KHR, vao, sizeof buf, &len, buf);
    CHECK_GL(GL_INVALID_VALUE);

    /* The message says which rule. */
    drain();
    glObjectLabelKHR(GL_SAMPLER_KHR, 1, -1, "x");
    CHECK_GL(GL_INVALID_ENUM);
    CHECK(fetch() == 1);
    CHECK(strstr(got.text, "glObjectLabelKHR: GL_INVALID_ENUM (0x0500): identifier is 0x82E6 (GL_SAMPLER_KHR)") ==
          got.text);
    glObjectLabelKHR(GL_TEXTURE, 4321, -1, "x");
    CHECK_GL(GL_INVALID_VALUE);
    CHECK(fetch() == 1);
    CHECK(strstr(got.text, "glObjectLabelKHR: GL_INVALID_VALUE (0x0501): name is 4321") ==
          got.text);

    /* No pointer names an object in ES 1.1 (no sync objects). */
    glObjectPtrLabelKHR(&len, -1, "x");
    CHECK_GL(GL_INVALID_VALUE);
    glGetObjectPtrLabelKHR(&len, sizeof buf, &len, buf);
    CHECK_GL(GL_INVALID_VALUE);
    drain();
}

int main(void)
{
    ct_init(8, 8);
#define GET(type, name) name = (type)eglGetProcAddress(#name)
    GET(PFNGLDEBUGMESSAGECONTROLKHRPROC, glDebugMessageControlKHR);
    GET(PFNGLDEBUGMESSAGEINSERTKHRPROC, glDebugMessageInsertKHR);
    GET(PFNGLDEBUGMESSAGECALLBACKKHRPROC, glDebugMessageCallbackKHR);
    GET(PFNGLGETDEBUGMESSAGELOGKHRPROC, glGetDebugMessageLogKHR);
    GET(PFNGLPUSHDEBUGGROUPKHRPROC, glPushDebugGroupKHR);
    GET(PFNGLPOPDEBUGGROUPKHRPROC, glPopDebugGroupKHR);
    GET(PFNGLOBJECTLABELKHRPROC, glObjectLabelKHR);
    GET(PFNGLGETOBJECTLABELKHRPROC, glGetObjectLabelKHR);
    GET(PFNGLOBJECTPTRLABELKHRPROC, glObjectPtrLabelKHR);
    GET(PFNGLGETOBJECTPTRLABELKHRPROC, glGetObjectPtrLabelKHR);
    GET(PFNGLGETPOINTERVKHRPROC, glGetPointervKHR);
    GET(PFNGLGENRENDERBUFFERSOESPROC, glGenRenderbuffersOES);
    GET(PFNGLBINDRENDERBUFFEROESPROC, glBindRenderbufferOES);
    GET(PFNGLGENFRAMEBUFFERSOESPROC, glGenFramebuffersOES);
    GET(PFNGLBINDFRAMEBUFFEROESPROC, glBindFramebufferOES);
    GET(PFNGLGENVERTEXARRAYSOESPROC, glGenVertexArraysOES);
    GET(PFNGLBINDVERTEXARRAYOESPROC, glBindVertexArrayOES);
    GET(PFNGLDELETEVERTEXARRAYSOESPROC, glDeleteVertexArraysOES);
#undef GET
    CHECK(glDebugMessageControlKHR && glDebugMessageInsertKHR && glDebugMessageCallbackKHR &&
          glGetDebugMessageLogKHR && glPushDebugGroupKHR && glPopDebugGroupKHR &&
          glObjectLabelKHR && glGetObjectLabelKHR && glObjectPtrLabelKHR &&
          glGetObjectPtrLabelKHR && glGetPointervKHR && glGenRenderbuffersOES &&
          glBindRenderbufferOES && glGenFramebuffersOES && glBindFramebufferOES &&
          glGenVertexArraysOES && glBindVertexArrayOES && glDeleteVertexArraysOES);
    if (!glDebugMessageControlKHR || !glDebugMessageInsertKHR || !glDebugMessageCallbackKHR ||
        !glGetDebugMessageLogKHR || !glPushDebugGroupKHR || !glPopDebugGroupKHR ||
        !glObjectLabelKHR || !glGetObjectLabelKHR || !glObjectPtrLabelKHR ||
        !glGetObjectPtrLabelKHR || !glGetPointervKHR || !glGenRenderbuffersOES ||
        !glBindRenderbufferOES || !glGenFramebuffersOES || !glBindFramebufferOES ||
        !glGenVertexArraysOES || !glBindVertexArrayOES || !glDeleteVertexArraysOES)
        return ct_done();
    CHECK(strstr((const char *)glGetString(GL_EXTENSIONS), "GL_KHR_debug") != NULL);

    check_errors_in_words();
    check_log();
    check_insert_errors();
    check_control();
    check_callback();
    check_groups();
    check_labels();
    CHECK_GL(GL_NO_ERROR);
    return ct_done();
}
