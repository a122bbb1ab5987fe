"""``python -m bearingsim`` runs the command-line interface."""

from .cli import main

main()
