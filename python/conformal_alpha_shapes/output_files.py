"""The files the module writes (``Result.write_ply``, the tiles' parts,
manifest and merged file): each is written beside its final name and renamed
into place, so that a file under its final name is always whole; it gets the
mode any new file gets (0666 less the umask: -rw-r--r-- under umask 022),
and errors name the caller's path, not the temporary file's."""

import errno
import os
import secrets

__all__ = ["atomic_write"]


def _naming(error, path):
    """``error`` (an OSError about the temporary file) about ``path`` instead."""
    if isinstance(error, OSError) and error.errno is not None:
        return type(error)(error.errno, error.strerror, path)
    return error


def _create_temporary(path):
    """A new empty file beside ``path``, created as any file is (the umask applies); its name."""
    folder, name = os.path.split(os.path.abspath(path))
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_CLOEXEC", 0)
    for _ in range(100):
        temporary = os.path.join(folder, f".{name}.{secrets.token_hex(4)}.part")
        try:
            os.close(os.open(temporary, flags, 0o666))
            return temporary
        except FileExistsError:
            continue
        except OSError as error:
            raise _naming(error, path) from None
    raise FileExistsError(errno.EEXIST, "no free temporary name beside it", path)


def atomic_write(path, write):
    """Calls ``write(temporary_path)`` and renames the file to ``path``: never half written.

    Raises OSError naming ``path`` (a missing folder, no permission, a full
    disk); an error of ``write`` that names the temporary file is raised
    naming ``path``. The temporary file is removed on any error.
    """
    path = os.fspath(path)
    temporary = _create_temporary(path)
    try:
        write(temporary)
        os.replace(temporary, path)
    except BaseException as error:
        try:
            os.unlink(temporary)
        except OSError:
            pass
        if isinstance(error, OSError):
            raise _naming(error, path) from None
        if isinstance(error, (RuntimeError, ValueError)) and temporary in str(error):
            try:
                renamed = type(error)(str(error).replace(temporary, path))
            except Exception:
                raise error from None
            raise renamed from None
        raise
