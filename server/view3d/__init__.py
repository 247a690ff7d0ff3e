"""The live 3D view: viser, the feeds that draw a trial or a replay in it, and replay cursors."""
