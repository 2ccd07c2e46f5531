"""The GUI's start-up script (paraview --script): see gui_session.py."""
import gui_session

gui_session.setup()
