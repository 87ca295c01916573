using System.Runtime.InteropServices;

namespace Billiards.App.Native;

/// <summary>
/// Loads a native library by the first of its platform names that resolves: beside the executable
/// first (where a published folder may carry it, e.g. glfw3.dll on Windows), then the system's.
/// </summary>
internal static class NativeLoader
{
    /// <summary>The library's handle, or a <see cref="DllNotFoundException"/> naming every candidate tried.</summary>
    public static nint Load(string what, params string[] candidates)
    {
        foreach (string name in candidates)
        {
            string beside = Path.Combine(AppContext.BaseDirectory, name);
            if ((File.Exists(beside) && NativeLibrary.TryLoad(beside, out nint handle)) || NativeLibrary.TryLoad(name, out handle))
            {
                return handle;
            }
        }
        throw new DllNotFoundException($"{what} not found (tried {string.Join(", ", candidates)})");
    }

    /// <summary>An exported symbol, or an exception naming it.</summary>
    public static nint Export(nint library, string name) =>
        NativeLibrary.TryGetExport(library, name, out nint address)
            ? address
            : throw new EntryPointNotFoundException($"native function {name} not found");
}
