"""Writing a file so that it is either complete or absent.

    with replacing(path) as tmp:
        write tmp

writes PATH.tmp and renames it to PATH when the block ends normally; if the
block raises, PATH.tmp is removed and PATH stays as it was.
"""
import contextlib
import os


@contextlib.contextmanager
def replacing(path, suffix=".tmp"):
    tmp = path + suffix
    try:
        yield tmp
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)
