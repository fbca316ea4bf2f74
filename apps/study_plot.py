"""The shared end of the benchmark scripts' plots (balance_benchmark.py, scaling_benchmark.py): a dashed target
line, the axis labels, the legend, and the PNG beside the CSV."""


def finish(fig, ax, png, xlabel, ylabel, target):
    """Draws the target as a dashed horizontal line, labels the axes and saves the figure as png."""
    ax.axhline(target, color="gray", ls="--", lw=0.8)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.legend()
    fig.tight_layout()
    fig.savefig(png, dpi=120)
