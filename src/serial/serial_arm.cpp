// The serial-arm plugin: URDF via urdfdom into Orocos KDL.
