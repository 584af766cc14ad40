//! The simulation pipeline, one module per stage of MuJoCo's computation chapter.
