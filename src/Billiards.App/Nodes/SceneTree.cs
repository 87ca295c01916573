using Billiards.App.Input;

namespace Billiards.App.Nodes;

/// <summary>
/// Owns the root node and drives the lifecycle: <see cref="Start"/> once, then per frame
/// <see cref="Process"/>, <see cref="PhysicsProcess"/> per fixed step, <see cref="Input"/> per
/// event and <see cref="Draw"/>.
/// </summary>
public sealed class SceneTree
{
    /// <summary>Creates a tree around a root node (not yet started).</summary>
    public SceneTree(Node root)
    {
        ArgumentNullException.ThrowIfNull(root);
        if (root.Parent is not null)
        {
            throw new ArgumentException("the root must not have a parent", nameof(root));
        }
        Root = root;
        root.SetTree(this);
    }

    /// <summary>The root node.</summary>
    public Node Root { get; }

    /// <summary>True after <see cref="Start"/>.</summary>
    public bool IsStarted { get; private set; }

    /// <summary>Makes every node ready (children before parents).</summary>
    public void Start()
    {
        if (IsStarted)
        {
            throw new InvalidOperationException("the tree has already started");
        }
        IsStarted = true;
        Root.PropagateReady();
    }

    /// <summary>Runs one frame's Process over the tree.</summary>
    public void Process(double dt) => Root.PropagateProcess(dt);

    /// <summary>Runs one fixed step's PhysicsProcess over the tree.</summary>
    public void PhysicsProcess(double dt) => Root.PropagatePhysicsProcess(dt);

    /// <summary>Delivers an input event; returns true when a node handled it.</summary>
    public bool Input(InputEvent e) => Root.PropagateInput(e);

    /// <summary>Lets every node draw into the frame.</summary>
    public void Draw(FrameBuilder frame) => Root.PropagateDraw(frame);

    /// <summary>The first node of a type, or null.</summary>
    public T? Find<T>() where T : class => Root.Find<T>();
}
