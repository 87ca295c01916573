using System.Runtime.InteropServices;

namespace Billiards.App.Native;

/// <summary>Loads a system library by the first of its platform names that resolves.</summary>
internal static class NativeLoader
{
    /// <summary>The library's handle, or a <see cref="DllNotFoundException"/> naming every candidate tried.</summary>
    public static nint Load(string what, params string[] candidates)
    {
        foreach (string name in candidates)
        {
            if (NativeLibrary.TryLoad(name, out nint handle))
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
