namespace Billiards.App.Platform;

/// <summary>
/// Makes a context for offscreen drawing: EGL surfaceless where it works (headless Linux, CI),
/// otherwise a hidden GLFW window.
/// </summary>
internal static class OffscreenContext
{
    /// <summary>A current context; throws <see cref="InvalidOperationException"/> with every route's reason when none works.</summary>
    public static IGlContext Create()
    {
        IGlContext? context = EglSurfacelessContext.TryCreate(out string? eglError);
        if (context is not null)
        {
            return context;
        }
        context = HiddenGlfwContext.TryCreate(out string? glfwError);
        return context ?? throw new InvalidOperationException($"no OpenGL 3.3 context for offscreen rendering: {eglError}; {glfwError}");
    }
}
