namespace Billiards.App.Platform;

/// <summary>An OpenGL 3.3 core context that the renderer draws with.</summary>
internal interface IGlContext : IDisposable
{
    /// <summary>How the context was made (for messages), e.g. "EGL surfaceless (llvmpipe)".</summary>
    string Description { get; }

    /// <summary>Makes the context current on the calling thread.</summary>
    void MakeCurrent();

    /// <summary>Releases the context from the calling thread (so another thread may make it current).</summary>
    void ReleaseCurrent();

    /// <summary>Address of a GL function by name, or 0.</summary>
    nint GetProcAddress(string name);
}
