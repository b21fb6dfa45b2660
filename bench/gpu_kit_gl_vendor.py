"""Prints GL_VENDOR of a GL context made through EGL on the given platform, for the GPU kit's
summary (bench/gpu_kit_run.sh): the CLI's statistics name the renderer and version but not the
vendor. Loads the kit's own libEGL and libOpenGL (argv[1] is the kit's library folder) so that
it sees the display the kit's binaries see.
    python3 gl_vendor.py LIBDIR [device|surfaceless|default]
"""
import ctypes
import sys

EGL_NONE = 0x3038
EGL_DEFAULT_DISPLAY = None
EGL_PLATFORM_DEVICE_EXT = 0x313F
EGL_PLATFORM_SURFACELESS_MESA = 0x31DD
EGL_EXTENSIONS = 0x3055
EGL_RENDERABLE_TYPE = 0x3040
EGL_SURFACE_TYPE = 0x3033
EGL_PBUFFER_BIT = 0x0001
EGL_OPENGL_BIT = 0x0008
EGL_OPENGL_API = 0x30A2
GL_VENDOR = 0x1F00

lib = sys.argv[1]
want = sys.argv[2] if len(sys.argv) > 2 else ""
# --stats names a GPU's device after the platform ("device /dev/dri/card0 (CUDA device 0)");
# Mesa's CPU device is "software device": both are the device platform.
if "device" in want:
    want = "device"
egl = ctypes.CDLL(lib + "/libEGL.so.1")
gl = ctypes.CDLL(lib + "/libOpenGL.so.0")
egl.eglGetProcAddress.restype = ctypes.c_void_p
egl.eglGetProcAddress.argtypes = [ctypes.c_char_p]
egl.eglQueryString.restype = ctypes.c_char_p
egl.eglQueryString.argtypes = [ctypes.c_void_p, ctypes.c_int]
egl.eglGetDisplay.restype = ctypes.c_void_p
egl.eglGetDisplay.argtypes = [ctypes.c_void_p]
egl.eglInitialize.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p]
egl.eglChooseConfig.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.POINTER(ctypes.c_void_p), ctypes.c_int,
                                ctypes.POINTER(ctypes.c_int)]
egl.eglCreateContext.restype = ctypes.c_void_p
egl.eglCreateContext.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p,
                                 ctypes.c_void_p]
egl.eglMakeCurrent.argtypes = [ctypes.c_void_p] * 4
gl.glGetString.restype = ctypes.c_char_p
gl.glGetString.argtypes = [ctypes.c_uint]


def proc(name, restype, *argtypes):
    address = egl.eglGetProcAddress(name.encode())
    return ctypes.CFUNCTYPE(restype, *argtypes)(address) if address else None


def displays():
    """The displays in the order headless/EglHeadlessContext.cpp tries them."""
    extensions = (egl.eglQueryString(None, EGL_EXTENSIONS) or b"").decode().split()
    platform_display = proc("eglGetPlatformDisplayEXT", ctypes.c_void_p, ctypes.c_int,
                            ctypes.c_void_p, ctypes.c_void_p)
    if want in ("", "device") and "EGL_EXT_device_enumeration" in extensions and platform_display:
        query = proc("eglQueryDevicesEXT", ctypes.c_uint, ctypes.c_int, ctypes.c_void_p,
                     ctypes.POINTER(ctypes.c_int))
        devices = (ctypes.c_void_p * 16)()
        count = ctypes.c_int(0)
        if query and query(16, devices, ctypes.byref(count)):
            for i in range(count.value):
                yield platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], None)
    if want in ("", "surfaceless") and "EGL_MESA_platform_surfaceless" in extensions:
        yield platform_display(EGL_PLATFORM_SURFACELESS_MESA, None, None)
    if want in ("", "default"):
        yield egl.eglGetDisplay(EGL_DEFAULT_DISPLAY)


for display in displays():
    if not display or not egl.eglInitialize(display, None, None):
        continue
    egl.eglBindAPI(EGL_OPENGL_API)
    attributes = (ctypes.c_int * 5)(EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                    EGL_OPENGL_BIT, EGL_NONE)
    config = ctypes.c_void_p()
    found = ctypes.c_int(0)
    if not egl.eglChooseConfig(display, attributes, ctypes.byref(config), 1,
                               ctypes.byref(found)) or found.value == 0:
        # EGL_KHR_no_config_context, as the headless context does where it can.
        config = ctypes.c_void_p()
    context = egl.eglCreateContext(display, config, None, None)
    if not context or not egl.eglMakeCurrent(display, None, None, context):
        continue
    vendor = gl.glGetString(GL_VENDOR)
    if vendor:
        print(vendor.decode())
        sys.exit(0)
sys.exit(1)
