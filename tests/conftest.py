"""Shared test settings: hypothesis runs few, deadline-free examples so the suite stays fast."""
from hypothesis import settings

settings.register_profile("linecontact", max_examples=40, deadline=None)
settings.load_profile("linecontact")
