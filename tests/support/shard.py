"""--shard K/N for the test scripts that run a list of cases (run_corpus.py, run_readme_commands.py): the K-th of N
shares is every N-th item from the K-th, so N processes side by side run the whole list."""


def add_shard_option(parser, what):
    parser.add_argument("--shard", default="1/1", metavar="K/N",
                        help=f"run only the K-th of N shares of the {what} (every N-th from the K-th)")


def take_share(parser, shard, items):
    """The items of share K/N; a usage error (exit 2) when K/N is not 1 <= K <= N."""
    try:
        k, n = (int(x) for x in shard.split("/"))
        if not 1 <= k <= n:
            raise ValueError
    except ValueError:
        parser.error(f"--shard needs K/N with 1 <= K <= N, got '{shard}'")
    return items[k - 1::n]
