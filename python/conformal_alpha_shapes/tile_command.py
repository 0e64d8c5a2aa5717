"""The command line of tiled runs (``python3 -m conformal_alpha_shapes.tiles``,
whose ``main`` runs it): its flags read into ``process_tiles``'s arguments,
and the module's messages given the flags' names."""

import argparse

# the Python keywords in the module's messages, and the flags that set them
_FLAGS = {"scales": "--alpha", "radii": "--radius", "rings": "--rings", "estimator": "--estimator",
          "denoise_neighbors": "--denoise-neighbors", "denoise": "--denoise", "extraction": "--extraction",
          "tile_points": "--tile-points", "radii, rings": "--radius, --rings", "classes": "--classes",
          "returns": "--returns"}


def flag_message(message):
    """A message of the module with the program's flag for the keyword it names."""
    for keyword in sorted(_FLAGS, key=len, reverse=True):
        if message.startswith(keyword + ":"):
            return _FLAGS[keyword] + message[len(keyword):]
    return message


def arguments(argv):
    """The parsed command line (argparse exits with status 2 on a bad one)."""
    parser = argparse.ArgumentParser(
        prog="python3 -m conformal_alpha_shapes.tiles",
        description="The program conformal_curvature's job on a cloud split into tiles, on Dask: "
                    "parts in DIR/parts (binary PLY, the fields of curvatures.ply plus input_index), "
                    "DIR/manifest.json, and with --merge DIR/curvatures.ply in input order.")
    parser.add_argument("input", help="binary .ply (x y z [nx ny nz]), .npy (N x 3 or N x 6), .xyz or .las")
    parser.add_argument("--output", required=True, metavar="DIR",
                        help="the run's folder, readable and writable by every worker")
    parser.add_argument("--tile-points", type=int, default=1_000_000, metavar="N",
                        help="core points per tile (default 1000000)")
    engine = parser.add_mutually_exclusive_group()
    engine.add_argument("--workers", type=int, metavar="W",
                        help="worker processes of the embedded cluster on 127.0.0.1 (default: one per core)")
    engine.add_argument("--scheduler", metavar="ADDRESS", help="an existing Dask scheduler (tcp:// or tls://)")
    parser.add_argument("--tls-ca-file", metavar="FILE",
                        help="TLS: the certificate authority's file (with --scheduler tls://...)")
    parser.add_argument("--tls-cert", metavar="FILE", help="TLS: this client's certificate")
    parser.add_argument("--tls-key", metavar="FILE", help="TLS: this client's private key")
    parser.add_argument("--merge", action="store_true", help="also write DIR/curvatures.ply in input order")
    parser.add_argument("--las", action="store_true",
                        help="with --merge, write DIR/curvatures.las (LAS 1.4, named extra bytes) instead")
    parser.add_argument("--classes", default="", metavar="LIST", help="LAS input: keep these classes (e.g. 2,6)")
    parser.add_argument("--drop-withheld", action="store_true", help="LAS input: leave out withheld points")
    parser.add_argument("--returns", default="all", metavar="WHICH", help="LAS input: first, last or all returns")
    parser.add_argument("--alpha", default="auto", metavar="LIST", help="comma list of scales: auto and/or values")
    parser.add_argument("--radius", default=None, metavar="LIST",
                        help="comma list of radii: values, multiples of the spacing (4s), auto; "
                             "default auto,2s,4s,8s,16s unless --rings is given")
    parser.add_argument("--rings", default="", metavar="LIST", help="comma list of ring sizes from 1 to 100")
    parser.add_argument("--estimator", default="quadric", metavar="NAME")
    parser.add_argument("--denoise", default="auto", metavar="MODE", help="auto, on or off")
    parser.add_argument("--denoise-neighbors", default=None, metavar="K")
    parser.add_argument("--extraction", default="front", metavar="NAME", help="front or solid")
    parser.add_argument("--halo", type=float, default=None, metavar="SPACINGS",
                        help="the halo's width in spacings (default: from the largest radius, see the manual)")
    parser.add_argument("--threads", type=int, default=1, help="threads per tile (default 1)")
    parser.add_argument("--quiet", action="store_true", help="no progress and no summary")
    args = parser.parse_args(argv)
    # else Dask fails on connecting with a message that names no flag, or ignores the files
    tls = (args.scheduler or "").startswith("tls://")
    if tls and not (args.tls_ca_file and args.tls_cert and args.tls_key):
        parser.error(f"the scheduler at {args.scheduler} needs --tls-ca-file, --tls-cert and --tls-key")
    if not tls and (args.tls_ca_file or args.tls_cert or args.tls_key):
        parser.error("--tls-ca-file, --tls-cert and --tls-key are for a --scheduler at a tls:// address")
    return args


def _split_list(text):
    return [item for item in text.split(",") if item] if text else []


def security(args):
    """The TLS settings of the client, with the TLS flags given (else None)."""
    if not args.tls_ca_file:
        return None
    from distributed.security import Security
    return Security(tls_ca_file=args.tls_ca_file, tls_client_cert=args.tls_cert,
                    tls_client_key=args.tls_key, require_encryption=True)


def options(args):
    """The keyword arguments of ``process_tiles`` but ``security``, from the
    flags; a ring size or ``--denoise-neighbors`` that is not an integer
    raises ValueError with the keyword's message."""
    rings = _split_list(args.rings)
    radii = _split_list(args.radius) if args.radius is not None else ([] if rings else
                                                                      ["auto", "2s", "4s", "8s", "16s"])
    ring_sizes = []
    for ring in rings:
        try:
            ring_sizes.append(int(ring))
        except ValueError:
            raise ValueError(f"rings: not a ring size: '{ring}' (expected an integer from 1 to 100)") from None
    neighbors = None
    if args.denoise_neighbors is not None:
        try:
            neighbors = int(args.denoise_neighbors)
        except ValueError:
            raise ValueError(f"denoise_neighbors: not an integer: '{args.denoise_neighbors}'") from None
    classes = []
    for item in _split_list(args.classes):
        try:
            classes.append(int(item))
        except ValueError:
            raise ValueError(f"classes: not a LAS class from 0 to 255: '{item}'") from None
    return dict(tile_points=args.tile_points, workers=args.workers, scheduler=args.scheduler, merge=args.merge,
                las=args.las, classes=classes, drop_withheld=args.drop_withheld, returns=args.returns,
                scales=_split_list(args.alpha), radii=radii, rings=ring_sizes, estimator=args.estimator,
                denoise=args.denoise, denoise_neighbors=neighbors, extraction=args.extraction,
                halo=args.halo, threads=args.threads, quiet=args.quiet)
