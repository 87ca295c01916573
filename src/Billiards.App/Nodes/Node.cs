using Billiards.App.Input;

namespace Billiards.App.Nodes;

/// <summary>
/// A node of the game's scene tree, in the manner of Godot: a node has children, a lifecycle
/// (<see cref="Ready"/> once, then <see cref="Process"/> every frame, <see cref="PhysicsProcess"/>
/// every fixed step, <see cref="Input"/> per event and <see cref="Draw"/> per frame) and signals,
/// which are plain C# events declared by each script.
/// </summary>
/// <remarks>
/// Order, as Godot's: Ready runs children first, so a parent can rely on its children being
/// ready; Process, PhysicsProcess and Draw run the parent first, then children in the order they
/// were added (so later children draw on top); Input runs the other way round (the last child
/// first, the parent last), so overlays added late see events first, and stops at the first
/// node that handles it.
/// </remarks>
public class Node
{
    private readonly List<Node> _children = [];

    /// <summary>Creates a node; the name defaults to the type's name.</summary>
    public Node(string? name = null) => Name = name ?? GetType().Name;

    /// <summary>The node's name, for finding it and for debugging.</summary>
    public string Name { get; set; }

    /// <summary>The parent, or null for the root or a detached node.</summary>
    public Node? Parent { get; private set; }

    /// <summary>The children in the order they were added.</summary>
    public IReadOnlyList<Node> Children => _children;

    /// <summary>The tree the node belongs to, or null while detached.</summary>
    public SceneTree? Tree { get; private set; }

    /// <summary>True once <see cref="Ready"/> has run.</summary>
    public bool IsReady { get; private set; }

    /// <summary>Signal: the node became ready (after its children).</summary>
    public event Action<Node>? Readied;

    /// <summary>
    /// Adds a child. If this node is already in a started tree the child (and its subtree) becomes
    /// ready at once, as in Godot.
    /// </summary>
    public T AddChild<T>(T child) where T : Node
    {
        ArgumentNullException.ThrowIfNull(child);
        if (child.Parent is not null)
        {
            throw new InvalidOperationException($"node '{child.Name}' already has the parent '{child.Parent.Name}'");
        }
        if (ReferenceEquals(child, this) || IsDescendantOf(child))
        {
            throw new InvalidOperationException($"adding '{child.Name}' under '{Name}' would make a cycle");
        }
        _children.Add(child);
        child.Parent = this;
        child.SetTree(Tree);
        if (Tree is { IsStarted: true })
        {
            child.PropagateReady();
        }
        return child;
    }

    /// <summary>Removes a child (and its subtree) from this node.</summary>
    public void RemoveChild(Node child)
    {
        if (!_children.Remove(child))
        {
            throw new InvalidOperationException($"'{child.Name}' is not a child of '{Name}'");
        }
        child.Parent = null;
        child.SetTree(null);
    }

    /// <summary>The first node of type <typeparamref name="T"/> in this subtree (this node included, depth first), or null.</summary>
    public T? Find<T>() where T : class
    {
        if (this is T self)
        {
            return self;
        }
        foreach (var child in _children)
        {
            if (child.Find<T>() is { } found)
            {
                return found;
            }
        }
        return null;
    }

    /// <summary>The first node of type <typeparamref name="T"/> in the whole tree, or null (a sibling script's dependency).</summary>
    public T? FindInTree<T>() where T : class => (Tree?.Root ?? Root()).Find<T>();

    /// <summary>Like <see cref="FindInTree{T}"/>, but a missing node is a programming error.</summary>
    public T GetInTree<T>() where T : class =>
        FindInTree<T>() ?? throw new InvalidOperationException($"'{Name}' needs a {typeof(T).Name} in the tree, and there is none");

    /// <summary>Called once when the node enters a started tree, after its children.</summary>
    protected virtual void Ready()
    {
    }

    /// <summary>Called every frame with the frame's real duration (s).</summary>
    protected virtual void Process(double dt)
    {
    }

    /// <summary>Called every fixed physics step (s).</summary>
    protected virtual void PhysicsProcess(double dt)
    {
    }

    /// <summary>Called for every input event; return true to stop it here.</summary>
    protected virtual bool Input(InputEvent e) => false;

    /// <summary>Called every frame to put what this node shows into the frame.</summary>
    protected virtual void Draw(FrameBuilder frame)
    {
    }

    internal void PropagateReady()
    {
        // Iterate over a copy: a Ready may add nodes, which then get ready through AddChild.
        foreach (var child in _children.ToArray())
        {
            if (!child.IsReady)
            {
                child.PropagateReady();
            }
        }
        if (!IsReady)
        {
            IsReady = true;
            Ready();
            Readied?.Invoke(this);
        }
    }

    internal void PropagateProcess(double dt)
    {
        Process(dt);
        foreach (var child in _children.ToArray())
        {
            child.PropagateProcess(dt);
        }
    }

    internal void PropagatePhysicsProcess(double dt)
    {
        PhysicsProcess(dt);
        // Indexing, not a copy: this runs 250 times a second and the physics step adds no nodes.
        for (int i = 0; i < _children.Count; i++)
        {
            _children[i].PropagatePhysicsProcess(dt);
        }
    }

    internal bool PropagateInput(InputEvent e)
    {
        for (int i = _children.Count - 1; i >= 0; i--)
        {
            if (_children[i].PropagateInput(e))
            {
                return true;
            }
        }
        return Input(e);
    }

    internal void PropagateDraw(FrameBuilder frame)
    {
        Draw(frame);
        for (int i = 0; i < _children.Count; i++)
        {
            _children[i].PropagateDraw(frame);
        }
    }

    internal void SetTree(SceneTree? tree)
    {
        Tree = tree;
        foreach (var child in _children)
        {
            child.SetTree(tree);
        }
    }

    private Node Root()
    {
        var node = this;
        while (node.Parent is not null)
        {
            node = node.Parent;
        }
        return node;
    }

    private bool IsDescendantOf(Node node)
    {
        for (var p = Parent; p is not null; p = p.Parent)
        {
            if (ReferenceEquals(p, node))
            {
                return true;
            }
        }
        return false;
    }
}
